package org.miron.generator;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.EcoreUtil2;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.Import;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.formats.BtFormatConverter;
import org.miron.bt.formats.Conversion;
import org.miron.bt.formats.ConversionProblem;
import org.miron.bt.nodes.BuiltinNodes;
import org.miron.bt.util.BtFormats;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.util.Imports;

/**
 * Weaves the variation points bound to behaviour-tree nodes into a copy of the nominal tree
 * (docs/generators.md, "The woven behaviour tree"):
 *  - an enum varpoint becomes a Switch over {vp_sel} (VariantSwitches);
 *  - a numeric varpoint bound to an attribute replaces its value by the port {vp};
 *  - the keys the runtime writes into the main tree's blackboard ({vp_sel}, {vp}) are remapped on
 *    every subtree call between the main tree and the subtree that reads them (BlackboardKeys);
 *  - the main tree's root is wrapped once in the monitoring Parallel (MonitoringParallel).
 * Trees of other files stay there and are reached through includes relative to the woven tree
 * (computed on URIs); only the files holding targets are copied into the woven tree.
 * The woven tree is written for BehaviorTree.CPP 3 or 4 (by default the version of the imported
 * tree): copied trees of the other version are converted (BtFormatConverter), and what the weaver
 * adds uses the version's idioms (WovenNodes).
 */
public class BtWeaver {
    private final List<GenerationError> errors;
    /** Where the woven tree will be written: includes are relative to it. */
    private final URI wovenTree;
    /** The requested BehaviorTree.CPP format, or null for the imported tree's. */
    private final Integer requestedFormat;

    public BtWeaver(List<GenerationError> errors, URI wovenTree) {
        this(errors, wovenTree, null);
    }

    public BtWeaver(List<GenerationError> errors, URI wovenTree, Integer format) {
        this.errors = errors;
        this.wovenTree = wovenTree;
        this.requestedFormat = format;
    }

    /** The woven tree, or null when the model imports no behaviour tree. */
    public BTModel weave(AdaptationModel m) {
        List<Resource> btFiles = btFiles(m.models);
        List<SampledVariationPoint> bound = m.varpoints.stream()
                .filter(vp -> vp.varpoint.getBinding() instanceof BtBinding).toList();
        if (btFiles.isEmpty()) {
            return null; // nothing to weave into; BT bindings without a .bt import are validation errors
        }
        // The nominal tree: the imported .bt that names a main tree, else the first one.
        Resource primary = btFiles.stream().filter(r -> root(r).getMain_tree_to_execute() != null).findFirst()
                .orElse(btFiles.get(0));
        Map<SampledVariationPoint, List<EObject>> targets = new LinkedHashMap<>();
        Set<Resource> woven = new LinkedHashSet<>();
        woven.add(primary);
        for (SampledVariationPoint vp : bound) {
            List<EObject> selected = BindingTargets.select(vp, errors);
            targets.put(vp, selected);
            selected.forEach(target -> woven.add(target.eResource()));
        }
        EcoreUtil.Copier copier = new EcoreUtil.Copier();
        List<BTModel> copies = woven.stream().map(r -> (BTModel) copier.copy(r.getContents().get(0))).toList();
        copier.copyReferences();
        int format = requestedFormat != null ? requestedFormat : BtFormats.version(root(primary));
        for (BTModel copy : copies) {
            convert(copy, format, copier);
        }
        for (List<EObject> selected : targets.values()) {
            for (EObject target : selected) {
                if (!EcoreUtil.isAncestor(copies, copier.get(target))) {
                    // e.g. value_B of a BlackboardCheck, which becomes part of a Precondition's script
                    errors.add(new GenerationError(target, "cannot weave into this element in a BehaviorTree.CPP "
                            + format + " tree: the conversion to version " + format + " rewrites it"));
                }
            }
        }
        if (!errors.isEmpty()) {
            return null;
        }
        WovenNodes nodes = new WovenNodes(format, copier);
        VariantSwitches switches = new VariantSwitches(nodes);

        // Blackboard keys the runtime writes into the main tree (vp_sel, vp), by the tree reading them.
        Map<BehaviorTree, Set<String>> readers = new LinkedHashMap<>();
        for (SampledVariationPoint vp : bound) {
            for (EObject target : targets.get(vp)) {
                EObject copy = copier.get(target);
                String key = vp.isEnum() ? vp.selection() : vp.name;
                if (copy instanceof Attribute attribute) {
                    attribute.setValue("{" + key + "}");
                } else if (copy instanceof TreeNode node && vp.isEnum()) {
                    switches.insert(vp, node);
                }
                BehaviorTree reader = EcoreUtil2.getContainerOfType(copy, BehaviorTree.class);
                if (reader != null && (vp.isEnum() || copy instanceof Attribute)) {
                    readers.computeIfAbsent(reader, tree -> new LinkedHashSet<>()).add(key);
                }
            }
        }
        new BlackboardKeys(nodes).expose(copies, readers);

        BTModel out = nodes.factory.createBTModel();
        BTModel first = copies.get(0);
        out.getAttributes().addAll(new ArrayList<>(first.getAttributes()));
        for (String path : new WovenIncludes(errors, format, wovenTree).of(woven, bound)) {
            Import include = nodes.factory.createImport();
            include.setImportURI(path);
            out.getImports().add(include);
        }
        copies.forEach(copy -> out.getTrees().addAll(new ArrayList<>(copy.getTrees())));
        out.setNodesmodel(first.getNodesmodel());
        nameMainTree(out, nodes);
        List<SampledVariationPoint> monitored = bound.stream().filter(SampledVariationPoint::isEnum).toList();
        if (!monitored.isEmpty()) {
            new MonitoringParallel(nodes, errors).wrap(out, monitored, m);
            if (out.getNodesmodel() != null) {
                out.getNodesmodel().setContent(MonitoringParallel.declareVariantAction(out.getNodesmodel().getContent()));
            }
        }
        return out;
    }

    /** The behaviour-tree files the models import, each once, in import order. */
    private static List<Resource> btFiles(List<MironModel> models) {
        Set<Resource> files = new LinkedHashSet<>();
        for (MironModel model : models) {
            for (org.miron.dsl.roqme.Import imp : model.getImports()) {
                Resource r = Imports.load(imp);
                if (r != null && !r.getContents().isEmpty() && r.getContents().get(0) instanceof BTModel) {
                    files.add(r);
                }
            }
        }
        return new ArrayList<>(files);
    }

    private static BTModel root(Resource btFile) {
        return (BTModel) btFile.getContents().get(0);
    }

    /**
     * BehaviorTree.CPP 3 runs a file's only tree when no main_tree_to_execute is given, counting
     * the included trees too. A woven file with several trees or includes therefore names its
     * main tree; a main tree without ID (BehaviorTree.CPP's tutorial form) gets one first.
     */
    private static void nameMainTree(BTModel out, WovenNodes nodes) {
        if (out.getMain_tree_to_execute() != null || (out.getTrees().size() <= 1 && out.getImports().isEmpty())
                || out.getTrees().isEmpty()) {
            return;
        }
        BehaviorTree main = out.getTrees().get(0);
        if (main.getName() == null || main.getName().isEmpty()) {
            Set<String> taken = new HashSet<>();
            out.getTrees().forEach(tree -> taken.add(tree.getName()));
            String id = "MainTree";
            for (int k = 2; taken.contains(id); k++) {
                id = "MainTree" + k;
            }
            main.setName(id);
        }
        out.getAttributes().add(nodes.attribute("main_tree_to_execute", main.getName()));
    }

    /** A copied file of the other version, converted; what has no equivalent is reported at the original. */
    private void convert(BTModel copy, int format, EcoreUtil.Copier copier) {
        if (BtFormats.version(copy) == format) {
            return;
        }
        Map<EObject, EObject> originals = new HashMap<>();
        copier.forEach((original, copied) -> originals.put(copied, original));
        Conversion conversion = BtFormatConverter.convert(copy, format);
        // Targets are found through the copier: point it at the nodes that replaced converted ones.
        for (Map.Entry<EObject, EObject> entry : new ArrayList<>(copier.entrySet())) {
            EObject replacement = conversion.getReplacements().get(entry.getValue());
            if (replacement != null) {
                entry.setValue(replacement);
            }
        }
        for (ConversionProblem problem : conversion.getProblems()) {
            EObject original = originals.get(problem.getElement());
            errors.add(new GenerationError(original != null ? original : originals.get(copy),
                    "cannot weave a BehaviorTree.CPP " + format + " tree: " + problem.getMessage()));
        }
        // _autoremap="false" only marks a converted SubTreePlus for the way back; a woven tree is not converted back.
        for (SubtreeNode call : EcoreUtil2.eAllOfType(copy, SubtreeNode.class)) {
            call.getAttributes().stream()
                    .filter(a -> BuiltinNodes.AUTOREMAP.equals(a.getName()) && "false".equals(a.getValue()))
                    .findFirst().ifPresent(call.getAttributes()::remove);
        }
    }
}
