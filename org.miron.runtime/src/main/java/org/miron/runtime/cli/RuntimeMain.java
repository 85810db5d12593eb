package org.miron.runtime.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * Runs the runtime components directly ({@code broker}, {@code engine}, {@code skill-mock},
 * {@code play}); the top-level {@code miron} command registers the same classes as subcommands.
 */
@Command(name = "miron-runtime", mixinStandardHelpOptions = true,
        subcommands = {BrokerCommand.class, EngineCommand.class, SkillMockCommand.class, PlayCommand.class, ExecuteCommand.class},
        description = "MIRoN runtime components.")
public final class RuntimeMain implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "missing command: broker, engine, skill-mock or play");
    }

    public static void main(String[] args) {
        // One-line log records: "2026-11-21 08:00:00 INFO engine: ..."
        if (System.getProperty("java.util.logging.SimpleFormatter.format") == null) {
            System.setProperty("java.util.logging.SimpleFormatter.format", "%1$tF %1$tT %4$s %5$s%6$s%n");
        }
        System.exit(new CommandLine(new RuntimeMain()).execute(args));
    }
}
