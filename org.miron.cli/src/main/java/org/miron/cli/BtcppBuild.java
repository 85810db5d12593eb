package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Finds miron-btcpp-run (cpp/miron_btcpp built on BehaviorTree.CPP 4.8.2 into build/miron-btcpp),
 * building it with scripts/ensure-btcpp-plugin.sh when it is missing (the first time: a few minutes).
 */
final class BtcppBuild {
    static final String RUNNER = "build/miron-btcpp/miron-btcpp-run";

    private BtcppBuild() {
    }

    /** The runner, or null when it cannot be built (the script said why on err). */
    static Path runner(Path home, PrintWriter err) throws InterruptedException {
        Path runner = home.resolve(RUNNER).toAbsolutePath();
        Path script = home.resolve("scripts/ensure-btcpp-plugin.sh");
        if (!Files.isExecutable(runner) && Files.isExecutable(script)) {
            err.println("miron demo: building miron-btcpp-run (BehaviorTree.CPP 4.8.2 and the MIRoN plugin; once)...");
            err.flush();
            try {
                new ProcessBuilder(script.toString()).redirectOutput(ProcessBuilder.Redirect.INHERIT)
                        .redirectError(ProcessBuilder.Redirect.INHERIT).start().waitFor();
            } catch (IOException e) {
                err.println("miron demo: cannot run " + script + ": " + e.getMessage());
            }
        }
        return Files.isExecutable(runner) ? runner : null;
    }
}
