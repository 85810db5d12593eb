package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.miron.cli.monitor.ReplayMonitor;
import org.miron.cli.monitor.ReplayServer;
import org.miron.cli.monitor.ReplayState;
import org.miron.runtime.recording.Btlog;
import org.miron.runtime.recording.BtlogReader;
import org.miron.runtime.recording.BusLogReader;
import org.miron.runtime.recording.RecordedTree;
import org.miron.runtime.recording.Recording;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code miron replay FILE.btlog}: what a recording holds, and with --monitor the live page over it with a time slider. */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Replay a recording (FILE.btlog, BehaviorTree.CPP's FileLogger2 format, written by `--record` of "
                + "execute, demo or miron-btcpp-run; the bus beside it in FILE.bus.jsonl): prints what it holds; with "
                + "--monitor serves the live page over it with a time slider (docs/diagrams.md, \"Recording and replay\").",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { "0:replayed (without --monitor)", "2:not a recording, or the port cannot be served",
                ExitCodes.SIGTERM + " (--monitor)", ExitCodes.SIGINT + " (--monitor)" })
public final class ReplayCommand implements Callable<Integer> {
    @Parameters(paramLabel = "FILE.btlog", description = "the recording")
    Path file;

    @Option(names = "--bus-log", paramLabel = "FILE", description = "the run's bus log (default: FILE.bus.jsonl beside the recording, if there)")
    Path busLog;

    @Option(names = "--monitor", paramLabel = "PORT",
            description = "serve the live page over the recording on http://127.0.0.1:PORT/ until stopped")
    Integer monitorPort;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        if (!Files.isRegularFile(file)) {
            return error(file + ": error: no such file");
        }
        Recording recording;
        RecordedTree tree;
        List<BusLogReader.BusEvent> bus = List.of();
        Path busFile = busLog != null ? busLog : Btlog.busLogOf(file);
        try {
            recording = BtlogReader.read(file);
            tree = RecordedTree.parse(recording.treeXml());
            if (busLog != null || Files.isRegularFile(busFile)) {
                bus = BusLogReader.read(busFile);
            }
        } catch (IOException e) {
            return error("miron replay: error: " + e.getMessage());
        }
        ReplayState replay = new ReplayState(recording, tree, bus, ReplayMonitor.plainNames());
        out.println("recording: " + file + ": tree " + tree.mainTreeId() + " (" + tree.nodes().size() + " nodes), "
                + recording.transitions().size() + " transitions over " + seconds(replay.durationMillis()) + " s");
        if (recording.trailingBytes() > 0) {
            out.println("  cut short: the last " + recording.trailingBytes() + " bytes are an incomplete transition (left out)");
        }
        long decisions = bus.stream().filter(e -> e.topic().equals(org.miron.runtime.bus.Topics.DECISION)).count();
        out.println("bus: " + (bus.isEmpty() && !Files.isRegularFile(busFile) ? "no " + busFile.getFileName() + " (statuses only)"
                : bus.size() + " events, " + decisions + " decisions, " + replay.marks().size() + " adaptations"));
        replay.marks().forEach(m -> out.println("  " + seconds(m.path("at").asLong()) + " s  adaptation #" + m.path("seq").asLong()
                + " " + m.path("changed")));
        out.flush();
        if (monitorPort == null) {
            return 0;
        }
        ReplayServer server;
        try {
            server = ReplayMonitor.start(monitorPort, "MIRoN replay: " + file.getFileName(), tree, replay);
        } catch (IOException | RuntimeException e) {
            return error("miron replay: error: cannot serve the replay on 127.0.0.1:" + monitorPort + ": " + e.getMessage());
        }
        out.println("replay monitor: " + server.url());
        out.flush();
        return UntilShutdown.run("replay", server);
    }

    private static String seconds(long millis) {
        return String.format(Locale.ROOT, "%.3f", millis / 1000.0);
    }

    private int error(String message) {
        spec.commandLine().getErr().println(message);
        spec.commandLine().getErr().flush();
        return 2;
    }
}
