package org.miron.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.miron.runtime.roqme.LiveProvider;
import org.miron.runtime.roqme.Replay;
import org.miron.runtime.roqme.expr.CompiledModel;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code miron roqme run|replay MODEL}: the RoQME QoS Metrics Provider (docs/roqme-provider.md) on a
 * .roqme or .miron source or a generated name.roqme.json.
 */
@Command(name = "roqme", mixinStandardHelpOptions = true,
        description = "The RoQME QoS Metrics Provider: computes the properties of a RoQME model (.roqme, .miron or "
                + "a generated name.roqme.json) from the contexts, live on the bus (run) or from a recorded trace (replay).",
        subcommands = { RoqmeCommand.Run.class, RoqmeCommand.ReplayTrace.class })
public final class RoqmeCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "missing subcommand: run or replay");
    }

    /** The options both subcommands share. */
    static final class ModelOptions {
        @Parameters(index = "0", paramLabel = "MODEL", description = "a .roqme model, a .miron model (its RoQME part), both generated in memory, "
                + "or the name.roqme.json `miron generate` writes for them")
        Path model;

        @Option(names = "--period", paramLabel = "MS", description = "tick: estimates are computed every MS (default: ${DEFAULT-VALUE})")
        long period = 1000;

        @Option(names = "--param", paramLabel = "NAME=VALUE", description = "overrides a param's default (repeatable)")
        Map<String, String> params = new LinkedHashMap<>();

        /** The compiled model, or null after printing why not (file:line:col: error [code]: message). */
        CompiledModel load(String command, PrintWriter err) {
            if (period <= 0) {
                err.println("miron roqme " + command + ": error: --period must be positive, got " + period);
                return null;
            }
            return RoqmeSources.compile(model, new LinkedHashMap<>(params), err);
        }
    }

    @Command(name = "run", mixinStandardHelpOptions = true,
            description = "Run the provider on the bus: roqme.context in; roqme.estimate of every property each period, "
                    + "roqme.observation when an observation fires, roqme.status out.",
            exitCodeListHeading = ExitCodes.HEADING,
            exitCodeList = { "2:the model is refused (file:line:col), an unreadable --state file, bad usage", ExitCodes.SIGTERM,
                    ExitCodes.SIGINT })
    static final class Run implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Mixin
        ModelOptions options = new ModelOptions();

        @Option(names = "--status-interval", paramLabel = "MS",
                description = "re-publish roqme.status at least this often (default: ${DEFAULT-VALUE})")
        long statusInterval = 5000;

        @Option(names = "--state", paramLabel = "FILE", description = "keep the evidence in FILE across restarts "
                + "(written every second and on stop; default: evidence is lost on restart)")
        Path state;

        @Mixin
        BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

        @Mixin
        BrokerEndpoints.BusOut busOut = new BrokerEndpoints.BusOut();

        @Override
        public Integer call() {
            PrintWriter err = spec.commandLine().getErr();
            CompiledModel m = options.load("run", err);
            if (m == null) {
                return 2;
            }
            LiveProvider p = new LiveProvider(m, options.period, statusInterval, busIn.endpoint, busOut.endpoint);
            if (state != null) {
                try {
                    p.state(state);
                } catch (IOException e) {
                    err.println("miron roqme run: error: " + e.getMessage());
                    return 2;
                }
            }
            p.start();
            System.out.println("miron roqme run: model " + m.model().model() + ", " + m.observations().size()
                    + " observations, period " + options.period + " ms, bus " + busIn.endpoint + " / " + busOut.endpoint);
            return UntilShutdown.run("roqme run", p);
        }
    }

    @Command(name = "replay", mixinStandardHelpOptions = true,
            description = "Replay a JSON Lines trace of roqme.context bodies (each with its time in ms) on a virtual "
                    + "clock and print every tick's estimates and fired observations.",
            exitCodeListHeading = ExitCodes.HEADING,
            exitCodeList = { "0:replayed", "1:the model or a trace line is refused (file:line[:col]: error)",
                    "2:unreadable file or bad usage" })
    static final class ReplayTrace implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Mixin
        ModelOptions options = new ModelOptions();

        @Option(names = "--trace", required = true, paramLabel = "FILE", description = "JSON Lines: one roqme.context body per line, with \"time\" in ms")
        Path trace;

        @Option(names = "--start", paramLabel = "MS", description = "clock start (default: the first record's time)")
        Long start;

        @Option(names = "--ticks", paramLabel = "N", description = "ticks to print (default: through the tick holding the last record)")
        Long ticks;

        @Option(names = "--format", paramLabel = "csv|jsonl", description = "csv: tick,time,<properties>,fired; jsonl: one object per tick (default: csv)")
        String format = "csv";

        @Option(names = {"-o", "--out"}, paramLabel = "FILE", description = "write there instead of the standard output")
        Path out;

        @Override
        public Integer call() {
            PrintWriter err = spec.commandLine().getErr();
            Replay.Format f;
            switch (format) {
                case "csv" -> f = Replay.Format.CSV;
                case "jsonl" -> f = Replay.Format.JSONL;
                default -> {
                    err.println("miron roqme replay: error: --format must be csv or jsonl, got " + format);
                    return 2;
                }
            }
            if (ticks != null && ticks < 0) {
                err.println("miron roqme replay: error: --ticks must not be negative");
                return 2;
            }
            if (!Files.isReadable(trace)) {
                err.println("miron roqme replay: error: cannot read the trace " + trace);
                return 2;
            }
            CompiledModel m = options.load("replay", err);
            if (m == null) {
                return 1;
            }
            Replay replay = new Replay(m, options.period, start, ticks, f);
            try (BufferedReader in = Files.newBufferedReader(trace)) {
                Writer w = out == null ? spec.commandLine().getOut() : Files.newBufferedWriter(out);
                try {
                    replay.run(in, trace.toString(), w);
                } finally {
                    if (out != null) {
                        w.close();
                    }
                }
                return 0;
            } catch (Replay.TraceException e) {
                err.println(e.getMessage());
                return 1;
            } catch (IOException e) {
                err.println("miron roqme replay: error: " + e.getMessage());
                return 2;
            }
        }
    }
}
