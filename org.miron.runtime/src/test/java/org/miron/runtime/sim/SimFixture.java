package org.miron.runtime.sim;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.testkit.RepositoryRoot;

/** The intralogistics example generated into a folder, with its world: a simulation's setup. */
final class SimFixture {
    private SimFixture() {
    }

    /** Generates examples/NAME/MODEL.miron into {@code out} and reads {@code world} against it. */
    static Setup setup(String example, String model, Path world, Path out) throws Exception {
        Path miron = RepositoryRoot.resolve("examples").resolve(example).resolve(model + ".miron");
        Files.createDirectories(out);
        ModelLoader loader = new ModelLoader();
        List<Resource> resources = new ArrayList<>(List.of(loader.load(new File(miron.toString()))));
        BatchGeneration.Outcome outcome = new BatchGeneration(loader, WeightPolicy.NEED).run(resources, BatchGeneration.folder(out));
        if (!outcome.succeeded()) {
            throw new IllegalStateException("cannot generate " + miron + ": " + outcome.validation());
        }
        IoModel io = IoModel.load(out.resolve(model + ".io.json"));
        var roqme = ModelReader.read(out.resolve(model + ".roqme.json"));
        Path tree = out.resolve(model + ".ext.xml");
        WorldModel w = WorldReader.read(world, Setup.env(tree, roqme));
        return new Setup(io, roqme, tree, w);
    }

    static Path intralogisticsWorld() {
        return RepositoryRoot.resolve("examples/intralogistics/world.json");
    }
}
