package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.logging.Level;
import java.util.logging.Logger;

import org.miron.cli.demo.Demo;
import org.miron.runtime.Endpoints;
import org.miron.runtime.engine.EngineStartException;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.skill.SkillTable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/**
 * `miron demo`: generates the intralogistics example and runs the whole loop on it in one JVM
 * (broker, engine, mock skill interface, BT executor, scenario player), telling each adaptation
 * as it happens and writing a timeline report at the end.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Runs the MIRoN loop on an example in one process: the battery drains and the robot docks, "
                + "safety drops and the velocity follows; writes OUT/report.html.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:the demo ran", "1:the model has errors", "2:usage or start-up error (e.g. no minizinc)" })
public class DemoCommand implements Callable<Integer> {
    private static final String EXAMPLE = "examples/intralogistics/";

    @Option(names = "--model", paramLabel = "FILE.miron", description = "the MIRoN model (default: the intralogistics example)")
    Path model;

    @Option(names = "--scenario", paramLabel = "FILE", description = "the scenario to play (default: the example's)")
    Path scenario;

    @Option(names = "--skills", paramLabel = "FILE", description = "the mock skill table (default: the example's)")
    Path skills;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "miron-demo",
            description = "where the generated model, the decision log and report.html go (default: ${DEFAULT-VALUE})")
    Path out;

    @Option(names = "--time-scale", paramLabel = "F", defaultValue = "1.0",
            description = "scenario time scale: 0.5 plays twice as fast (default: ${DEFAULT-VALUE})")
    double timeScale;

    @Option(names = "--bt-format", paramLabel = "3|4",
            description = "weave and run the behaviour tree as BehaviorTree.CPP 3 or 4 (default: the version of the model's tree)")
    Integer btFormat;

    @Option(names = "--backend", paramLabel = "NAME",
            description = "the engine's solver: native (in process, the default), minizinc (the reference) or both")
    String backend;

    @Option(names = "--verbose", description = "also show the components' own logs")
    boolean verbose;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        Path home = Path.of(System.getProperty("miron.home", "."));
        Path modelFile = model != null ? model : home.resolve(EXAMPLE + "intralogistics.miron");
        Path scenarioFile = scenario != null ? scenario : home.resolve(EXAMPLE + "demo/scenario.json");
        Path skillsFile = skills != null ? skills : home.resolve(EXAMPLE + "demo/skills.json");
        for (Path file : new Path[] { modelFile, scenarioFile, skillsFile }) {
            if (!Files.isRegularFile(file)) {
                return usage(file + ": error: no such file");
            }
        }
        if (!(timeScale > 0)) {
            return usage("--time-scale must be positive");
        }
        if (btFormat != null && btFormat != 3 && btFormat != 4) {
            return usage("--bt-format must be 3 or 4, not " + btFormat);
        }
        Path generated = out.resolve("model");
        String name = modelFile.getFileName().toString().replaceFirst("\\.miron$", "");
        PrintWriter console = spec.commandLine().getOut();
        console.println("MIRoN demo: generating " + modelFile + " into " + generated);
        CommandLine generate = MironCli.commandLine();
        generate.setOut(spec.commandLine().getOut());
        generate.setErr(spec.commandLine().getErr());
        List<String> arguments = new ArrayList<>(List.of("generate", "-o", generated.toString()));
        if (btFormat != null) {
            arguments.addAll(List.of("--bt-format", btFormat.toString()));
        }
        arguments.add(modelFile.toString());
        int status = generate.execute(arguments.toArray(String[]::new));
        if (status != 0) {
            return status;
        }
        if (!verbose) {
            // The narration tells what matters; component logs stay available with --verbose.
            Logger.getLogger("").setLevel(Level.SEVERE);
        }
        Scenario steps;
        SkillTable table;
        try {
            steps = Scenario.load(scenarioFile);
            table = SkillTable.load(skillsFile);
        } catch (IOException | RuntimeException e) {
            return usage("miron demo: error: " + e.getMessage());
        }
        Path tree = generated.resolve(name + ".ext.xml");
        console.println("MIRoN demo: broker, engine, skill interface mock, BT executor and scenario player start;"
                + " the scenario lasts about " + Math.round(lastStep(steps) * timeScale / 1000.0) + " s.");
        console.println("    time  who     what");
        Demo.Result result;
        try {
            result = new Demo(generated.resolve(name + ".io.json"), tree, steps, table,
                    out, Endpoints.freeLoopback(), console).timeScale(timeScale).backend(backend).run();
        } catch (EngineStartException e) {
            return usage("miron demo: error: " + e.getMessage());
        }
        console.println();
        console.println("MIRoN demo: " + result.adaptations() + " adaptations, " + result.parameterChanges()
                + " parameter changes applied by the skill interface, " + result.missions() + " missions finished.");
        console.println("  decision log: " + result.decisionLog());
        console.println("  report:       " + result.report() + "   (open it in a browser)");
        console.flush();
        return 0;
    }

    private static long lastStep(Scenario scenario) {
        return scenario.steps().stream().mapToLong(Scenario.Step::at).max().orElse(0);
    }

    private int usage(String message) {
        spec.commandLine().getErr().println(message);
        spec.commandLine().getErr().flush();
        return 2;
    }
}
