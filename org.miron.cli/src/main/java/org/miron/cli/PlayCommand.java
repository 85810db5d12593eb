package org.miron.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.miron.runtime.Endpoints;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.player.ScenarioPlayer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code miron play SCENARIO}: publishes RoQME contexts and estimates over time. */
@Command(name = "play", mixinStandardHelpOptions = true,
        description = "Play a timed scenario of RoQME estimates and contexts on the bus.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { "0:every step published", "1:interrupted", ExitCodes.STARTUP, ExitCodes.SIGTERM,
                ExitCodes.SIGINT })
public final class PlayCommand implements Callable<Integer> {
    @Parameters(paramLabel = "SCENARIO", description = "JSON array of {\"at\": ms, \"estimate\"|\"context\": {...}}")
    Path scenario;

    @Option(names = "--time-scale", description = "multiplies every 'at': 0.5 plays twice as fast (default: ${DEFAULT-VALUE})")
    double timeScale = 1.0;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Option(names = "--connect-timeout", paramLabel = "MS", description = "wait for the broker (default: ${DEFAULT-VALUE})")
    long connectTimeout = 10_000;

    @Override
    public Integer call() {
        Scenario s;
        try {
            s = Scenario.load(scenario);
        } catch (IOException e) {
            System.err.println("miron play: error: " + e.getMessage());
            return 2;
        }
        ScenarioPlayer player;
        try {
            player = new ScenarioPlayer(s, timeScale, busIn.endpoint);
        } catch (IllegalArgumentException e) {
            System.err.println("miron play: error: " + e.getMessage());
            return 2;
        }
        Thread hook = new Thread(player::close, "miron-play-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            int n = player.play(connectTimeout);
            System.out.println("miron play: " + n + " of " + s.steps().size() + " steps published");
            return 0;
        } catch (IllegalStateException e) {
            System.err.println("miron play: error: " + e.getMessage());
            return 2;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
                player.close();
            } catch (IllegalStateException ignored) {
                // JVM already shutting down: the hook closes the player
            }
        }
    }
}
