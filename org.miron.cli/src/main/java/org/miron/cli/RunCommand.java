package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;

import org.miron.cli.run.RobotSide;
import org.miron.cli.run.RunModel;
import org.miron.dds.config.BridgeConfig;
import org.miron.dds.config.ConfigException;
import org.miron.dds.config.ConfigReader;
import org.miron.dds.transport.IhmcTransport;
import org.miron.dds.types.DefinitionException;
import org.miron.runtime.engine.EngineOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code miron run MODEL.miron}: the MIRoN side of a robot in one process ({@link RobotSide}): broker,
 * RoQME provider, requirement monitors, engine and optionally the DDS bridge, with the options of
 * the separate commands.
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = "Run the MIRoN side of a robot in one process on a .miron model (generated in a JVM of its own, kept while unchanged): the broker "
                + "(as `miron broker`), the RoQME provider on its RoQME part (as `miron roqme run`), the requirement "
                + "monitors, the engine (as `miron engine`) and with --dds-bridge the DDS bridge. The executor and the "
                + "skill interface connect to the broker as they do to `miron broker`.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { "1:the model has errors (file:line:col, as miron check)",
                "2:start-up error (busy endpoint, bad file, missing minizinc, bridge configuration) or bad usage",
                ExitCodes.SIGTERM, ExitCodes.SIGINT })
public final class RunCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL.miron", description = "the MIRoN model")
    Path model;

    @Mixin
    BrokerSetup broker = new BrokerSetup();

    @Option(names = "--model-cache", paramLabel = "DIR", description = "where the model's generation is kept between runs "
            + "and reused while the model and all it imports are unchanged (default: $XDG_CACHE_HOME/miron/run or "
            + "~/.cache/miron/run)")
    Path modelCache;

    @Option(names = "--no-provider", description = "do not run the RoQME provider: the estimates come from elsewhere "
            + "(the original RoQME provider, or `miron roqme run` on another host)")
    boolean noProvider;

    @Option(names = "--period", paramLabel = "MS", description = "the provider's tick: estimates every MS (default: ${DEFAULT-VALUE})")
    long period = 1000;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "overrides a RoQME param's default (repeatable)")
    Map<String, String> params = new LinkedHashMap<>();

    @Mixin
    EngineSolving solving = new EngineSolving();

    @Option(names = "--status-interval", paramLabel = "MS",
            description = "re-publish each component's status at least this often (default: ${DEFAULT-VALUE})")
    long statusInterval = 5000;

    @Option(names = "--dds-bridge", paramLabel = "CONFIG", description = "also run the DDS / ROS 2 bridge with this mapping "
            + "(as `miron dds-bridge --config`; it answers change-parameter queries on --skill when a mapping names a parameter)")
    Path ddsBridge;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter out = spec.commandLine().getOut();
        if (period <= 0 || statusInterval <= 0) {
            err.println("miron run: error: --period and --status-interval must be positive");
            err.flush();
            return 2;
        }
        BridgeConfig bridge = null;
        if (ddsBridge != null) {
            try {
                bridge = ConfigReader.read(java.nio.file.Files.readString(ddsBridge), ddsBridge, IhmcTransport.CATALOG, err::println);
            } catch (IOException e) {
                return fail(err, "miron run: error: cannot read " + ddsBridge + ": " + e.getMessage(), 2);
            } catch (ConfigException e) {
                return fail(err, e.format(ddsBridge.toString()), 2);
            } catch (DefinitionException e) {
                return fail(err, e.format(), 2);
            }
        }
        RunModel generated;
        try {
            generated = RunModel.generate(model, noProvider ? null : new LinkedHashMap<>(params), err,
                    modelCache != null ? modelCache : RunModel.defaultCache());
        } catch (RunModel.Refused e) {
            return fail(err, e.getMessage(), e.status());
        }
        RobotSide.Options o = new RobotSide.Options();
        o.endpoints = broker.endpoints();
        o.cacheFile = broker.cacheFile;
        o.periodMs = period;
        o.providerStatusMs = statusInterval;
        o.bridge = bridge;
        o.bridgeStatusMs = statusInterval;
        o.engine = solving.applyTo(new EngineOptions(generated.ioJson()));
        o.engine.statusIntervalMs = statusInterval;
        out.println("miron run: model " + model.getFileName() + ": " + generated.origin());
        out.flush();
        RobotSide side = new RobotSide(generated, o).onStarted(RobotSide.printer(out, "miron run: "))
                .onRequirement(e -> {
                    out.println("miron run: requirement " + (e.verdict().equals(org.miron.runtime.requirement.RequirementEvent.MET)
                            ? e.name() + " met again" : e.describe()));
                    out.flush();
                });
        try {
            side.start();
        } catch (RobotSide.StartException e) {
            return fail(err, "miron run: error: " + e.getMessage() + " (nothing runs)", 2);
        }
        out.println("miron run: running " + model.getFileName() + "; SIGTERM or Ctrl-C stops it");
        out.flush();
        return UntilShutdown.run("run", side);
    }

    private static int fail(PrintWriter err, String message, int status) {
        err.println(message);
        err.flush();
        return status;
    }
}
