package org.miron.executor;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;

/**
 * The output ports a file's {@code <TreeNodesModel>} (or an included file's) declares for an
 * action ID, read once per file: what {@link ActionSpec#outputPorts()} carries to the factories.
 */
final class DeclaredOutputs {
    private final Map<Resource, Map<String, NodeDeclaration>> byFile = new HashMap<>();

    ActionSpec spec(TreeNode node, String id, ActionSpec.Kind kind, NodeInfo info) {
        Resource file = node.eResource();
        NodeDeclaration declared = file == null ? null : byFile.computeIfAbsent(file, NodeDeclarations::visibleFrom).get(id);
        return new ActionSpec(id, kind, info, declared == null ? Set.of() : declared.outputPorts());
    }
}
