package org.miron.diagram;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.sprotty.SEdge;
import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SModelElement;
import org.eclipse.sprotty.SNode;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.miron.dsl.MironStandaloneSetup;
import org.miron.testkit.RepositoryRoot;

/** Loads model files for the tests, and walks laid-out models. */
final class Models {
    private Models() {
    }

    /** A file with everything it imports, resolved (the MIRoN set-up registers BT too). */
    static Resource load(Path file) {
        XtextResourceSet set = MironStandaloneSetup.doSetup().getInstance(XtextResourceSet.class);
        Resource resource = set.getResource(URI.createFileURI(file.toAbsolutePath().toString()), true);
        EcoreUtil.resolveAll(resource);
        return resource;
    }

    static Resource example(String relative) {
        return load(RepositoryRoot.resolve("examples/" + relative));
    }

    /** Writes a held-back tree into a temporary file and loads it. */
    static Resource tree(String xml, String suffix) throws IOException {
        File file = File.createTempFile("diagram", suffix);
        file.deleteOnExit();
        Files.writeString(file.toPath(), xml);
        return load(file.toPath());
    }

    static List<SNode> frames(SGraph graph) {
        List<SNode> frames = new ArrayList<>();
        graph.getChildren().stream().filter(SNode.class::isInstance).map(SNode.class::cast).forEach(frames::add);
        return frames;
    }

    static List<SNode> nodes(SNode frame) {
        return frame.getChildren().stream().filter(SNode.class::isInstance).map(SNode.class::cast).toList();
    }

    static List<SEdge> edges(SModelElement container) {
        return container.getChildren().stream().filter(SEdge.class::isInstance).map(SEdge.class::cast).toList();
    }

    static List<SNode> allNodes(SGraph graph) {
        List<SNode> all = new ArrayList<>();
        frames(graph).forEach(f -> all.addAll(nodes(f)));
        return all;
    }
}
