package org.miron.runtime.groot;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.xml.parsers.DocumentBuilderFactory;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * The {@code <TreeNodesModel>} a tree file declares (its own, not its includes'): for each node ID
 * its kind element and ports, which FULLTREE writes for the application's nodes as the library
 * writes the models they were registered with (an output port stays an output port). A file that
 * cannot be read declares nothing: Groot2 then gets the ports the tree uses, as inputs.
 */
final class DeclaredModels {
    /** One declared node: its kind element (Action, Condition...) and its ports, name → port element. */
    record Model(String kind, Map<String, String> ports) {
    }

    private final Map<String, Model> models = new LinkedHashMap<>();

    static DeclaredModels none() {
        return new DeclaredModels();
    }

    static DeclaredModels of(Path treeFile) {
        DeclaredModels declared = new DeclaredModels();
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            NodeList lists = factory.newDocumentBuilder().parse(treeFile.toFile()).getElementsByTagName("TreeNodesModel");
            for (int i = 0; i < lists.getLength(); i++) {
                for (Node m = lists.item(i).getFirstChild(); m != null; m = m.getNextSibling()) {
                    if (m instanceof Element model && !model.getAttribute("ID").isEmpty()) {
                        declared.models.putIfAbsent(model.getAttribute("ID"), new Model(model.getTagName(), ports(model)));
                    }
                }
            }
        } catch (Exception unreadable) {
            // the tree was loaded from it already; a model we cannot read only makes the ports less precise
        }
        return declared;
    }

    private static Map<String, String> ports(Element model) {
        Map<String, String> ports = new LinkedHashMap<>();
        for (Node p = model.getFirstChild(); p != null; p = p.getNextSibling()) {
            if (p instanceof Element port && port.getTagName().endsWith("_port") && !port.getAttribute("name").isEmpty()) {
                ports.put(port.getAttribute("name"), port.getTagName());
            }
        }
        return ports;
    }

    Model get(String id) {
        return models.get(id);
    }
}
