package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.logging.Level;
import java.util.logging.Logger;

import org.miron.cli.demo.Demo;
import org.miron.cli.demo.DemoRequirements;
import org.miron.cli.demo.ScenarioInputs;
import org.miron.generator.RoqmeRuntimeModel;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.Endpoints;
import org.miron.runtime.engine.EngineStartException;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.skill.SkillTable;
import org.miron.runtime.sim.Durations;
import org.miron.runtime.sim.LiveWorld;
import org.miron.runtime.sim.WorldException;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/**
 * `miron demo`: generates a model (the intralogistics example by default) and runs the whole loop on
 * it in one JVM (broker, RoQME provider, engine, mock skill interface, BT executor), telling each
 * fired observation and adaptation as it happens and writing a timeline report at the end. The
 * robot's contexts come from a world the mock's skills act on (closed loop: demo/world.json next to
 * the model, else world.json next to it, or --world) or from a scripted scenario (demo/scenario.json
 * or --scenario; a scenario that does not fit the model is refused). README.md, docs/demo.md.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Runs the MIRoN loop on a model in one process: the skills act on a simulated world that publishes "
                + "the robot's contexts (closed loop; or a scripted scenario publishes them), the RoQME provider computes "
                + "the metrics from the model's observations, the engine adapts the behaviour tree and the skills; "
                + "writes OUT/report.html.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:the demo ran", "1:the model has errors", "2:usage or start-up error (e.g. no minizinc, a scenario input the model does not read)" })
public class DemoCommand implements Callable<Integer> {
    private static final String EXAMPLE = "examples/intralogistics/";

    @Option(names = "--model", paramLabel = "FILE.miron", description = "the MIRoN model (default: the intralogistics example)")
    Path model;

    @Option(names = "--world", paramLabel = "FILE", description = "run closed-loop on this world file (docs/simulator.md; "
            + "default: demo/world.json next to the model, else world.json next to it, unless the model has a demo/scenario.json)")
    Path world;

    @Option(names = "--duration", paramLabel = "TIME", defaultValue = "60s",
            description = "how long the world runs, in world time (closed loop only; default: ${DEFAULT-VALUE})")
    String duration;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "the world's random seed (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--scenario", paramLabel = "FILE", description = "play this scripted scenario instead of a world (default when "
            + "the model has no world: demo/scenario.json next to the model, else the intralogistics example's)")
    Path scenario;

    @Option(names = "--skills", paramLabel = "FILE", description = "the mock skill table, for a scripted scenario (default: demo/skills.json next to the model, else the intralogistics example's)")
    Path skills;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "miron-demo",
            description = "where the generated model, the decision log and report.html go (default: ${DEFAULT-VALUE})")
    Path out;

    @Option(names = "--time-scale", paramLabel = "F", defaultValue = "1.0",
            description = "time scale of the world or scenario: 0.5 runs twice as fast (default: ${DEFAULT-VALUE})")
    double timeScale;

    @Option(names = "--bt-format", paramLabel = "3|4",
            description = "weave and run the behaviour tree as BehaviorTree.CPP 3 or 4 (default: the version of the model's tree)")
    Integer btFormat;

    @Option(names = "--executor", paramLabel = "java|btcpp", defaultValue = "java",
            description = "who runs the woven tree: the Java executor (default) or the real BehaviorTree.CPP 4 through "
                    + "miron-btcpp-run and the MIRoN plugin (cpp/miron_btcpp, built on first use; implies --bt-format 4)")
    String executor;

    @Option(names = "--backend", paramLabel = "NAME",
            description = "the engine's solver: native (in process, the default), minizinc (the reference) or both")
    String backend;

    @Option(names = "--allow-unknown-inputs",
            description = "play a scenario even if it publishes contexts or estimates the model does not read "
                    + "(listed at start; by default the run is refused)")
    boolean allowUnknownInputs;

    @Option(names = "--no-provider",
            description = "do not run the RoQME provider: the scenario's estimate lines are the metrics")
    boolean noProvider;

    @Option(names = "--period", paramLabel = "MS", defaultValue = "1000",
            description = "the RoQME provider's tick in scenario time (default: ${DEFAULT-VALUE})")
    long period;

    @Option(names = "--monitor", paramLabel = "PORT",
            description = "serve the live monitor page (the running tree coloured by node status, the variation points "
                    + "and metrics) on http://127.0.0.1:PORT/ while the demo runs (docs/diagrams.md)")
    Integer monitorPort;

    @Option(names = "--groot", paramLabel = "PORT",
            description = "serve Groot2's protocol for the running tree on 127.0.0.1:PORT and PORT+1, as BehaviorTree.CPP 4's "
                    + "Groot2Publisher does (breakpoints, status, blackboards; docs/bt-semantics.md, \"Groot2\")")
    Integer grootPort;

    @Option(names = "--monitor-groot", paramLabel = "PORT",
            description = "the Groot2 server on 127.0.0.1 the live page debugs through (breakpoints, forced results, "
                    + "blackboards); default: --groot's PORT")
    Integer monitorGrootPort;

    @Option(names = "--record", paramLabel = "FILE.btlog",
            description = "record the run (either executor) as BehaviorTree.CPP's FileLogger2 does, what Groot2 and "
                    + "`miron replay` open, and the bus beside it in FILE.bus.jsonl (docs/diagrams.md, \"Recording and replay\")")
    Path record;

    @Option(names = "--verbose", description = "also show the components' own logs")
    boolean verbose;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        Path home = Path.of(System.getProperty("miron.home", "."));
        Path modelFile = model != null ? model : home.resolve(EXAMPLE + "intralogistics.miron");
        PrintWriter console = spec.commandLine().getOut();
        if (!Files.isRegularFile(modelFile)) {
            return usage(modelFile + ": error: no such file");
        }
        if (world != null && (scenario != null || skills != null)) {
            return usage("--world excludes --scenario and --skills: the world publishes the contexts and says how long its skills take");
        }
        Path worldFile = world != null ? world : scenario != null || skills != null ? null : worldOf(modelFile);
        Path scenarioFile = worldFile != null ? null : scenario != null ? scenario : input(modelFile, "scenario.json", home, console);
        Path skillsFile = worldFile != null ? null : skills != null ? skills : input(modelFile, "skills.json", home, console);
        for (Path file : new Path[] { worldFile, scenarioFile, skillsFile }) {
            if (file != null && !Files.isRegularFile(file)) {
                return usage(file + ": error: no such file");
            }
        }
        if (!(timeScale > 0)) {
            return usage("--time-scale must be positive");
        }
        long worldMs;
        try {
            worldMs = Durations.parseMs(duration);
        } catch (IllegalArgumentException e) {
            return usage(e.getMessage());
        }
        if (worldFile != null && noProvider) {
            return usage("--no-provider plays a scenario's scripted estimates: give --scenario too (a world publishes only contexts)");
        }
        if (record != null) {
            try {
                org.miron.runtime.recording.Btlog.checkExtension(record);
            } catch (IllegalArgumentException e) {
                return usage("miron demo: error: " + e.getMessage());
            }
        }
        if (btFormat != null && btFormat != 3 && btFormat != 4) {
            return usage("--bt-format must be 3 or 4, not " + btFormat);
        }
        Path btcppRunner = null;
        if (executor.equals("btcpp")) {
            if (btFormat != null && btFormat == 3) {
                return usage("--executor btcpp runs BehaviorTree.CPP 4 trees: drop --bt-format 3");
            }
            btFormat = 4;
            btcppRunner = BtcppBuild.runner(home, spec.commandLine().getErr());
            if (btcppRunner == null) {
                return usage("miron demo: error: miron-btcpp-run could not be built (scripts/ensure-btcpp-plugin.sh says why above)");
            }
        } else if (!executor.equals("java")) {
            return usage("--executor must be java or btcpp, not " + executor);
        }
        Path generated = out.resolve("model");
        String name = modelFile.getFileName().toString().replaceFirst("\\.miron$", "");
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
        Scenario steps = null;
        SkillTable table = null;
        IoModel io;
        CompiledModel roqme = null;
        RoqmeModel roqmeModel = null;
        Path tree = generated.resolve(name + ".ext.xml");
        try {
            io = IoModel.load(generated.resolve(name + ".io.json"));
            Path roqmeJson = generated.resolve(name + RoqmeRuntimeModel.SUFFIX);
            if (!noProvider && Files.isRegularFile(roqmeJson)) {
                roqmeModel = ModelReader.read(roqmeJson);
                roqme = Compiler.compile(roqmeModel, new LinkedHashMap<>());
            }
            if (worldFile == null) {
                steps = Scenario.load(scenarioFile);
                table = SkillTable.load(skillsFile);
            } else if (roqmeModel == null) {
                return usage("miron demo: error: " + modelFile.getFileName() + " has no RoQME part: a world's contexts "
                        + "have no metrics to feed; give a --scenario");
            }
        } catch (ModelException e) {
            return usage(e.getMessage());
        } catch (IOException | RuntimeException e) {
            return usage("miron demo: error: " + e.getMessage());
        }
        RequirementModel requirements;
        try {
            requirements = DemoRequirements.load(generated, name);
        } catch (IllegalArgumentException e) {
            return usage("miron demo: error: " + e.getMessage());
        }
        Endpoints endpoints = Endpoints.freeLoopback();
        LiveWorld liveWorld = null;
        if (worldFile != null) {
            try {
                liveWorld = ModelWorld.live(worldFile, tree, roqmeModel, seed, timeScale, endpoints.busIn());
            } catch (WorldException e) {
                PrintWriter err = spec.commandLine().getErr();
                e.problems().forEach(err::println);
                err.flush();
                return 1;
            } catch (IOException | RuntimeException e) {
                return usage("miron demo: error: " + worldFile + ": " + e.getMessage());
            }
        } else if (refused(steps, scenarioFile, io, roqmeModel, modelFile, console)) {
            return 2;
        }
        console.println("MIRoN demo: broker, " + (roqme == null ? "" : "RoQME provider, ")
                + "engine, skill interface mock, BT executor" + (worldFile == null
                        ? " and scenario player start; the scenario lasts about " + Math.round(lastStep(steps) * timeScale / 1000.0) + " s."
                        : " start; the skills act on " + home.toAbsolutePath().normalize().relativize(worldFile.toAbsolutePath().normalize())
                                + ", which publishes the robot's contexts (closed loop) for " + duration + " of world time, about "
                                + Math.round(worldMs * timeScale / 1000.0) + " s."));
        if (requirements != null) {
            console.println("MIRoN demo: the requirement monitors check " + requirements.requirements().size()
                    + " requirements of " + modelFile.getFileName() + " beside the engine, on "
                    + (worldFile != null ? "world" : "scenario") + " time.");
        }
        console.println("    time  who     what");
        Demo.Result result;
        try {
            result = new Demo(generated.resolve(name + ".io.json"), tree, steps, table,
                    out, endpoints, console).timeScale(timeScale).backend(backend).btcpp(btcppRunner)
                    .world(liveWorld, worldMs).requirements(requirements)
                    .provider(roqme, period).names(ModelNames.of(modelFile.toFile())).monitor(monitorPort).groot(grootPort)
                    .monitorGroot(monitorGrootPort != null ? monitorGrootPort : grootPort).record(record).run();
        } catch (EngineStartException e) {
            return usage("miron demo: error: " + e.getMessage());
        } catch (Demo.GrootBindException e) {
            return usage("miron demo: error: " + e.getMessage());
        } catch (java.net.BindException e) {
            return usage("miron demo: error: cannot serve the monitor on 127.0.0.1:" + monitorPort + ": " + e.getMessage());
        }
        console.println();
        console.println("MIRoN demo: " + result.adaptations() + " adaptations, " + result.parameterChanges()
                + " parameter changes applied by the skill interface, " + result.missions() + " missions finished.");
        console.println("  decision log: " + result.decisionLog());
        console.println("  report:       " + result.report() + "   (open it in a browser)");
        console.flush();
        return 0;
    }

    /** A scenario that does not fit the model is refused unless --allow-unknown-inputs; a scripted estimate is said. */
    private boolean refused(Scenario steps, Path scenarioFile, IoModel io, RoqmeModel roqmeModel, Path modelFile,
            PrintWriter console) {
        List<String> unknown = ScenarioInputs.unknown(steps, scenarioFile.getFileName().toString(), io,
                roqmeModel, modelFile.getFileName().toString());
        if (!unknown.isEmpty()) {
            PrintWriter err = spec.commandLine().getErr();
            unknown.forEach(err::println);
            if (!allowUnknownInputs) {
                usage("miron demo: error: " + scenarioFile + " was not written for " + modelFile.getFileName()
                        + " (the engine would decide on its defaults); give the model's own --scenario, or pass "
                        + "--allow-unknown-inputs to play it anyway");
                return true;
            }
            err.println("miron demo: warning: playing it anyway (--allow-unknown-inputs): the model ignores these inputs");
            err.flush();
        }
        long scripted = steps.steps().stream().filter(st -> st.topic().equals(Topics.ESTIMATE)).count();
        if (roqmeModel != null && scripted > 0) {
            console.println("MIRoN demo: " + scenarioFile.getFileName() + " scripts " + scripted + " estimates while the "
                    + "RoQME provider computes the metrics: both are published (--no-provider plays only the scripted ones)");
        }
        return false;
    }

    /**
     * The world the demo runs closed-loop on when neither --world nor --scenario is given:
     * {@code demo/world.json} next to the model, else {@code world.json} next to it, unless the
     * model's demo is scripted ({@code demo/scenario.json}); null: none.
     */
    private static Path worldOf(Path modelFile) {
        Path dir = modelFile.toAbsolutePath().getParent();
        if (dir == null) {
            return null;
        }
        if (Files.isRegularFile(dir.resolve("demo/world.json"))) {
            return dir.resolve("demo/world.json");
        }
        if (Files.isRegularFile(dir.resolve("demo/scenario.json"))) {
            return null;
        }
        return Files.isRegularFile(dir.resolve("world.json")) ? dir.resolve("world.json") : null;
    }

    /**
     * A demo input of the model: {@code <model dir>/demo/<file>} when there is one, else the
     * intralogistics example's, said on the console.
     */
    private static Path input(Path modelFile, String file, Path home, PrintWriter console) {
        Path dir = modelFile.toAbsolutePath().getParent();
        Path own = dir == null ? null : dir.resolve("demo").resolve(file);
        if (own != null && Files.isRegularFile(own)) {
            return own;
        }
        Path fallback = home.resolve(EXAMPLE + "demo/" + file);
        console.println("MIRoN demo: no demo/" + file + " next to " + modelFile.getFileName() + ": using " + fallback);
        return fallback;
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
