package org.miron.generator.cli;

import org.miron.runtime.cli.BrokerCommand;
import org.miron.runtime.cli.EngineCommand;
import org.miron.runtime.cli.ExecuteCommand;
import org.miron.runtime.cli.PlayCommand;
import org.miron.runtime.cli.SkillMockCommand;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The `miron` command: model checking, formatting and generation. */
@Command(name = "miron", mixinStandardHelpOptions = true, version = "miron 0.1",
        description = "MIRoN toolchain: behaviour trees, RoQME and MIRoN models for self-adaptive robots: check, "
                + "format and generate models; run the broker, engine, skill-interface mock, scenario player and "
                + "BT executor; or all of them at once with demo.",
        subcommands = { CheckCommand.class, FormatCommand.class, GenerateCommand.class, DemoCommand.class,
                BrokerCommand.class, EngineCommand.class, SkillMockCommand.class, PlayCommand.class,
                ExecuteCommand.class, CommandLine.HelpCommand.class })
public class MironCli implements Runnable {

    @Override
    public void run() {
        // No subcommand: a usage error, as for any other malformed command line.
        throw new CommandLine.ParameterException(new CommandLine(this), "missing command");
    }

    public static void main(String[] args) {
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
