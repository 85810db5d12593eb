package org.miron.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The `miron` command: checks, formats and generates models, and runs the runtime components. */
@Command(name = "miron", mixinStandardHelpOptions = true, versionProvider = BuildVersion.class,
        scope = CommandLine.ScopeType.INHERIT,
        description = "MIRoN toolchain: behaviour trees, RoQME and MIRoN models for self-adaptive robots: check, "
                + "format, convert (BehaviorTree.CPP 3 and 4), generate and render (SVG diagrams) models; serve them to editors (lsp); run the broker, engine, skill-interface "
                + "mock, scenario player and BT executor; or all of them at once with demo.",
        subcommands = { CheckCommand.class, FormatCommand.class, ConvertCommand.class, GenerateCommand.class, RenderCommand.class,
                DemoCommand.class, SimulateCommand.class, VerifyCommand.class, BrokerCommand.class, EngineCommand.class, SkillMockCommand.class, PlayCommand.class, RoqmeCommand.class, DdsBridgeCommand.class,
                RunCommand.class, ExecuteCommand.class, ReplayCommand.class, LspCommand.class, CommandLine.HelpCommand.class })
public class MironCli implements Runnable {

    @Override
    public void run() {
        // No subcommand: a usage error, as for any other malformed command line.
        throw new CommandLine.ParameterException(new CommandLine(this), "missing command");
    }

    public static void main(String[] args) throws InterruptedException {
        // `miron lsp` as editors start it goes straight to the server: building picocli's model of the
        // whole command tree costs about 0.3 s of CPU of a start-up the user waits for (docs/lsp.md).
        if (args.length == 1 && args[0].equals("lsp")) {
            System.exit(new LspCommand().call());
        }
        // One-line log records from the runtime components: "2026-11-21 08:00:00 INFO engine: ..."
        if (System.getProperty("java.util.logging.SimpleFormatter.format") == null) {
            System.setProperty("java.util.logging.SimpleFormatter.format", "%1$tF %1$tT %4$s %5$s%6$s%n");
        }
        System.exit(run(args));
    }

    /** Runs the command line and returns its exit code: 0 ok, 1 model errors, 2 usage. */
    public static int run(String... args) {
        return commandLine().execute(args);
    }

    /** The command line, for callers that redirect its output (tests, other tools). */
    public static CommandLine commandLine() {
        return new CommandLine(new MironCli());
    }
}
