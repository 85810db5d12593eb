package org.miron.bt.ide.server;

import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.lsp4j.SymbolKind;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper.DocumentSymbolKindProvider;

/**
 * Symbol kinds for the outline, breadcrumbs and workspace symbols of the three languages, so that
 * editors show each kind with its own icon (Xtext's default made every symbol a Property). Looked
 * up by metamodel and class, then by the class's super types (a BT control node is a Struct
 * whichever control it is).
 */
public class MironSymbolKinds extends DocumentSymbolKindProvider {
    private static final Map<String, SymbolKind> KINDS = Map.ofEntries(
            // Behaviour trees: a tree is a class, its nodes by role.
            Map.entry("bt.BehaviorTree", SymbolKind.Class),
            Map.entry("bt.TreeNodesModel", SymbolKind.Package),
            Map.entry("bt.Import", SymbolKind.File),
            Map.entry("bt.SubtreeNode", SymbolKind.Module),
            Map.entry("bt.ControlNode", SymbolKind.Struct),
            Map.entry("bt.DecoratorNode", SymbolKind.Interface),
            Map.entry("bt.Condition", SymbolKind.Boolean),
            Map.entry("bt.LeafNode", SymbolKind.Function),
            Map.entry("bt.TreeNode", SymbolKind.Object),
            Map.entry("bt.Attribute", SymbolKind.Key),
            // RoQME: what is observed, believed and estimated.
            Map.entry("roqme.RoqmeModel", SymbolKind.Namespace),
            Map.entry("roqme.Import", SymbolKind.File),
            Map.entry("roqme.TypeDefinition", SymbolKind.TypeParameter),
            Map.entry("roqme.EnumType", SymbolKind.Enum),
            Map.entry("roqme.EnumLiteral", SymbolKind.EnumMember),
            Map.entry("roqme.Context", SymbolKind.Variable),
            Map.entry("roqme.Param", SymbolKind.Constant),
            Map.entry("roqme.Var", SymbolKind.Variable),
            Map.entry("roqme.Timer", SymbolKind.Event),
            Map.entry("roqme.BeliefVariable", SymbolKind.Variable),
            Map.entry("roqme.Property", SymbolKind.Property),
            Map.entry("roqme.Observation", SymbolKind.Event),
            // MIRoN: variation points, their values, the rules that choose them and the requirements.
            Map.entry("miron.MironModel", SymbolKind.Namespace),
            Map.entry("miron.Import", SymbolKind.File),
            Map.entry("miron.VariationPoint", SymbolKind.Field),
            Map.entry("miron.BehaviorTreeLiteral", SymbolKind.EnumMember),
            Map.entry("miron.SampleValue", SymbolKind.Constant),
            Map.entry("miron.Rule", SymbolKind.Method),
            // a requirement is a contract the running robot is held to
            Map.entry("miron.Requirement", SymbolKind.Interface));

    @Override
    protected SymbolKind getSymbolKind(EClass type) {
        // Nearest first: a SubTreePlus is a SubtreeNode before it is a TreeNode.
        java.util.ArrayDeque<EClass> queue = new java.util.ArrayDeque<>(java.util.List.of(type));
        while (!queue.isEmpty()) {
            EClass next = queue.removeFirst();
            SymbolKind kind = KINDS.get(key(next));
            if (kind != null) {
                return kind;
            }
            queue.addAll(next.getESuperTypes());
        }
        return super.getSymbolKind(type);
    }

    private static String key(EClass type) {
        return (type.getEPackage() == null ? "" : type.getEPackage().getName()) + "." + type.getName();
    }
}
