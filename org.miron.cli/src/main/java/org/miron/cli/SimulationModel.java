package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import org.miron.generator.RoqmeRuntimeModel;
import org.miron.runtime.Json;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.sim.Policy;
import org.miron.runtime.sim.Setup;
import org.miron.runtime.sim.WorldException;
import org.miron.runtime.sim.WorldModel;
import org.miron.runtime.sim.WorldReader;

import picocli.CommandLine;

/**
 * What `miron simulate` and `miron verify` share: the model generated into {@code out/model} (as
 * `miron generate` writes it, errors as it prints them) and read back with the world file into a
 * {@link Setup}, the policies checked against the model before anything runs.
 */
final class SimulationModel {
    /** The setup, or the exit status to return (its reasons already printed). */
    record Loaded(Setup setup, int status) {
    }

    private SimulationModel() {
    }

    /** Writes OUT/summary.json, pretty-printed with a final newline. */
    static void writeSummary(Path out, JsonNode summary) throws IOException {
        Files.createDirectories(out);
        Files.writeString(out.resolve("summary.json"), Json.MAPPER.writerWithDefaultPrettyPrinter()
                .writeValueAsString(summary) + "\n", StandardCharsets.UTF_8);
    }

    /** Says on the console where the summary and the report are. */
    static void printWritten(Path out, PrintWriter console) {
        console.println("  summary: " + out.resolve("summary.json"));
        console.println("  report:  " + out.resolve("report.html") + "   (open it in a browser)");
        console.flush();
    }

    /**
     * @param modelError the exit status for a model the generator refuses (simulate: 1, verify: 2)
     */
    static Loaded load(Path model, Path world, Path out, List<Policy> policies, PrintWriter err, String command, int modelError)
            throws IOException {
        Path generated = out.resolve("model");
        String name = model.getFileName().toString().replaceFirst("\\.miron$", "");
        StringWriter log = new StringWriter();
        CommandLine generate = MironCli.commandLine();
        generate.setOut(new PrintWriter(log));
        generate.setErr(new PrintWriter(log));
        int status = generate.execute("generate", "-o", generated.toString(), model.toString());
        if (status != 0) {
            err.print(log);
            err.flush();
            return new Loaded(null, status == 1 ? modelError : status);
        }
        try {
            IoModel io = IoModel.load(generated.resolve(name + ".io.json"));
            RoqmeModel roqme = ModelReader.read(generated.resolve(name + RoqmeRuntimeModel.SUFFIX));
            Path tree = generated.resolve(name + ".ext.xml");
            Path requirementsFile = generated.resolve(name + ".requirements.json");
            RequirementModel requirements = Files.isRegularFile(requirementsFile) ? RequirementModel.load(requirementsFile) : null;
            WorldModel w = WorldReader.read(world, Setup.env(tree, roqme));
            for (Policy p : policies) {
                if (!p.adaptive()) {
                    p.configuration(io); // unknown varpoints and values are refused before anything runs
                }
            }
            return new Loaded(new Setup(io, roqme, tree, w, requirements), 0);
        } catch (WorldException e) {
            e.problems().forEach(err::println);
            err.flush();
            return new Loaded(null, 1);
        } catch (ModelException | IOException | RuntimeException e) { // a policy naming no varpoint, a tree the executor cannot build
            err.println("miron " + command + ": error: " + e.getMessage());
            err.flush();
            return new Loaded(null, 2);
        }
    }
}
