package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.miron.generator.RoqmeRuntimeModel;
import org.miron.runtime.Endpoints;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.runtime.sim.LiveWorld;
import org.miron.runtime.sim.WorldException;
import org.miron.runtime.skill.SkillBehaviour;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.runtime.skill.TableSkills;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code miron skill-mock}: the SmartSoft ComponentSkillInterface stand-in, its skills from a table
 * or acting on a world whose contexts it publishes on the bus (docs/simulator.md).
 */
@Command(name = "skill-mock", mixinStandardHelpOptions = true,
        description = "Run the mock SmartSoft skill interface (REP queries, PUB skill results). With --world, the skills "
                + "act on a simulated world (durations, effects, outcomes; change-parameter sets its parameters) and the "
                + "world's contexts are published on the bus (roqme.context) for the RoQME provider.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { ExitCodes.STARTUP, ExitCodes.SIGTERM, ExitCodes.SIGINT })
public final class SkillMockCommand implements Callable<Integer> {
    @Option(names = "--rep", description = "REP endpoint for queries (default: ${DEFAULT-VALUE})")
    String rep = Endpoints.DEFAULT_SKILL;

    @Option(names = "--pub", description = "PUB endpoint for skill results (default: ${DEFAULT-VALUE})")
    String pub = Endpoints.DEFAULT_SKILL_EVENTS;

    @Option(names = "--skills", paramLabel = "FILE",
            description = "skill table JSON: {\"GoTo\": {\"duration\": 1500, \"result\": \"SUCCESS\"}, \"*\": {...}}")
    Path skills;

    @Option(names = "--world", paramLabel = "FILE", description = "act on this world file instead of a table (needs --model)")
    Path world;

    @Option(names = "--model", paramLabel = "MODEL.miron", description = "the MIRoN model the world is checked against (with --world)")
    Path model;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "the world's random seed (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--time-scale", paramLabel = "F", defaultValue = "1.0",
            description = "the world's time scale: 0.5 runs it twice as fast as the wall clock (default: ${DEFAULT-VALUE})")
    double timeScale;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Spec
    CommandSpec spec;

    private PrintWriter err() {
        return spec.commandLine().getErr();
    }

    @Override
    public Integer call() {
        SkillBehaviour behaviour;
        try {
            if (world != null) {
                behaviour = world();
                if (behaviour == null) {
                    return 2;
                }
            } else {
                behaviour = new TableSkills(skills == null ? SkillTable.defaults() : SkillTable.load(skills));
            }
        } catch (IOException e) {
            err().println("miron skill-mock: error: cannot read skill table: " + e.getMessage());
            return 2;
        }
        SkillInterfaceMock mock;
        try {
            mock = new SkillInterfaceMock(rep, pub, behaviour).start();
        } catch (IllegalStateException e) {
            err().println("miron skill-mock: error: " + e.getMessage());
            return 2;
        }
        err().flush();
        if (behaviour instanceof LiveWorld live) {
            live.begin();
        }
        return UntilShutdown.run("skill-mock", mock);
    }

    /** The world checked against the model (generated into a temporary folder); null after saying why not. */
    private LiveWorld world() {
        if (model == null || skills != null || !(timeScale > 0)) {
            err().println("miron skill-mock: error: --world needs --model MODEL.miron, a positive --time-scale, and no --skills");
            return null;
        }
        if (!Files.isRegularFile(world) || !Files.isRegularFile(model)) {
            err().println((Files.isRegularFile(world) ? model : world) + ": error: no such file");
            return null;
        }
        try {
            Path generated = Files.createTempDirectory("miron-skill-mock");
            generated.toFile().deleteOnExit();
            String name = model.getFileName().toString().replaceFirst("\\.miron$", "");
            StringWriter log = new StringWriter();
            CommandLine generate = MironCli.commandLine();
            generate.setOut(new PrintWriter(log));
            generate.setErr(new PrintWriter(log));
            if (generate.execute("generate", "-o", generated.toString(), model.toString()) != 0) {
                err().print(log);
                return null;
            }
            return ModelWorld.live(world, generated.resolve(name + ".ext.xml"),
                    ModelReader.read(generated.resolve(name + RoqmeRuntimeModel.SUFFIX)), seed, timeScale, busIn.endpoint);
        } catch (WorldException e) {
            e.problems().forEach(err()::println);
            return null;
        } catch (IOException | ModelException | RuntimeException e) {
            err().println("miron skill-mock: error: " + e.getMessage());
            return null;
        }
    }
}
