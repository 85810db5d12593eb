package org.miron.generator;

import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.ecore.resource.Resource;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortModel;
import org.miron.bt.validation.BtVersions;
import org.miron.generator.standalone.ModelLoader;

/**
 * The examples and the weaver's golden cases, woven as BehaviorTree.CPP 3 and 4 trees: every
 * built-in in them (what the weaver adds and what it copies) is a built-in of that version whose
 * attributes are among the catalogue's ports for it, plus {@code name} (and, in version 4, the
 * pre/post-condition scripts any node takes). The explicit forms and subtree calls are left out:
 * their other attributes are the registered node's ports or a subtree's remappings.
 */
public class WovenBuiltinPortsTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void wovenBuiltinsUseOnlyTheirCataloguePorts() throws IOException {
        Set<String> seen = new TreeSet<>();
        int trees = 0;
        for (Path model : models()) {
            for (int format : new int[] { NodeCatalogue.V3, NodeCatalogue.V4 }) {
                Path out = temp.newFolder("v" + format + "-" + base(model)).toPath();
                Toolchain toolchain = new Toolchain();
                if (toolchain.generate(model.toString(), out.toString(), WeightPolicy.NEED, format) != 0) {
                    // A variant tree in a file of the other version that the woven tree includes.
                    assertTrue(model + ": " + toolchain.messages(),
                            toolchain.messages().contains("convert it with `miron convert --to"));
                    continue;
                }
                trees++;
                Resource woven = new ModelLoader().load(new File(out.resolve(base(model) + ".ext.xml").toString()));
                woven.getAllContents().forEachRemaining(o -> {
                    if (o instanceof TreeNode node) {
                        check(node, format, model).ifPresent(seen::add);
                    }
                });
            }
        }
        assertTrue("woven trees: " + trees, trees >= 30);
        // What the weaver writes was among them.
        assertTrue(seen.toString(), seen.containsAll(List.of("Parallel", "Repeat", "Switch2", "Switch5", "Sequence")));
    }

    private static Optional<String> check(TreeNode node, int format, Path model) {
        String where = model.getFileName() + " (version " + format + "): <" + node.getTag() + ">";
        NodeModel builtin = NodeCatalogue.find(node.getTag()).orElse(null);
        if (builtin == null || builtin.explicitForm() || builtin.kind() == NodeKind.SUBTREE) {
            return Optional.empty(); // a compact custom node, an explicit form or a subtree call
        }
        assertTrue(where + " is not a built-in of the version", builtin.accepts(node.getTag(), format));
        Set<String> allowed = new TreeSet<>(List.of("name"));
        builtin.ports(format).stream().map(PortModel::name).forEach(allowed::add);
        if (format == NodeCatalogue.V4) {
            allowed.addAll(BtVersions.SCRIPT_DIRECTIVES);
        }
        for (Attribute attribute : node.getAttributes()) {
            assertTrue(where + " has " + attribute.getName() + ", not among " + allowed,
                    allowed.contains(attribute.getName()));
        }
        for (PortModel port : builtin.ports(format)) {
            assertFalse(where + " lacks its required " + port.name(),
                    port.required() && node.attribute(port.name()) == null);
        }
        return Optional.of(builtin.tag());
    }

    private List<Path> models() throws IOException {
        return Toolchain.exampleAndWeavingModels(temp.newFolder("weaving").toPath());
    }

    private static String base(Path model) {
        return model.getFileName().toString().replaceFirst("\\.miron$", "");
    }
}
