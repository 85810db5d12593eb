package org.miron.runtime.recording;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.xml.parsers.DocumentBuilderFactory;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The tree of a recording's header as one tree again: the header writes each subtree instance as
 * its own {@code <BehaviorTree>} and each SubTree call empty, and since the library numbers a
 * subtree's nodes right after its call, the instance a {@code <SubTree _uid="u">} calls is the one
 * whose root has uid u + 1. Each node gets the id the live page's drawing gives it, its index path
 * from the root ("0", "0.1", "0.1.0": a SubTree's called root as its only child, as
 * org.miron.runtime.live.StatusPublisher numbers them).
 */
public final class RecordedTree {
    /** One node: uid, element (its registration name), name attribute, index path. */
    public record RecordedNode(int uid, String element, String name, String path) {
    }

    private final Element document;
    private final String mainTreeId;
    private final Map<Integer, RecordedNode> byUid = new LinkedHashMap<>();
    private final Map<Integer, Element> rootsByUid = new HashMap<>();
    private final Map<Integer, String> treeIdByRootUid = new HashMap<>();

    private RecordedTree(Element root) throws BtlogFormatException {
        document = root;
        List<Element> trees = childElements(root, "BehaviorTree");
        if (trees.isEmpty() || childElements(trees.get(0), null).isEmpty()) {
            throw new BtlogFormatException("the recording's tree has no <BehaviorTree> with a node");
        }
        for (Element tree : trees) {
            List<Element> nodes = childElements(tree, null);
            if (!nodes.isEmpty()) {
                int uid = uid(nodes.get(0));
                rootsByUid.put(uid, nodes.get(0));
                treeIdByRootUid.put(uid, tree.getAttribute("ID"));
            }
        }
        mainTreeId = trees.get(0).getAttribute("ID");
        walk(childElements(trees.get(0), null).get(0), "0");
    }

    /** Reads a recording's tree XML; malformed XML or nodes without uids are refused with the reason. */
    public static RecordedTree parse(String xml) throws BtlogFormatException {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            Element root = factory.newDocumentBuilder().parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)))
                    .getDocumentElement();
            return new RecordedTree(root);
        } catch (BtlogFormatException e) {
            throw e;
        } catch (Exception e) {
            throw new BtlogFormatException("the recording's tree XML cannot be read: " + e.getMessage());
        }
    }

    private void walk(Element element, String path) throws BtlogFormatException {
        int uid = uid(element);
        byUid.put(uid, new RecordedNode(uid, element.getTagName(), element.getAttribute("name"), path));
        List<Element> children = childElements(element, null);
        if (element.getTagName().equals("SubTree")) {
            Element called = rootsByUid.get(uid + 1);
            children = called == null ? List.of() : List.of(called);
        }
        for (int i = 0; i < children.size(); i++) {
            walk(children.get(i), path + "." + i);
        }
    }

    private static int uid(Element element) throws BtlogFormatException {
        try {
            return Integer.parseInt(element.getAttribute("_uid"));
        } catch (NumberFormatException e) {
            throw new BtlogFormatException("the recording's tree has a <" + element.getTagName() + "> without a _uid");
        }
    }

    private static List<Element> childElements(Element parent, String tag) {
        List<Element> out = new ArrayList<>();
        NodeList children = parent.getChildNodes();
        for (int i = 0; i < children.getLength(); i++) {
            if (children.item(i) instanceof Element e && (tag == null || e.getTagName().equals(tag))) {
                out.add(e);
            }
        }
        return out;
    }

    /**
     * The recorded tree as a BehaviorTree.CPP 4 file a loader reads (to draw it): each subtree
     * instance a tree of its own, {@code ID_<uid of its root>}, which its SubTree call calls; the
     * recording's {@code _uid} and {@code _fullpath} attributes left out.
     */
    public String loadableXml() {
        try {
            Element root = (Element) document.cloneNode(true);
            Map<Integer, String> instanceIds = new HashMap<>();
            List<Element> trees = childElements(root, "BehaviorTree");
            for (int i = 0; i < trees.size(); i++) {
                Element tree = trees.get(i);
                List<Element> nodes = childElements(tree, null);
                if (i > 0 && !nodes.isEmpty()) {
                    int rootUid = uid(nodes.get(0));
                    String id = tree.getAttribute("ID") + "_" + rootUid;
                    instanceIds.put(rootUid, id);
                    tree.setAttribute("ID", id);
                }
                tree.removeAttribute("_fullpath");
            }
            NodeList all = root.getElementsByTagName("*");
            for (int i = 0; i < all.getLength(); i++) {
                Element e = (Element) all.item(i);
                if (e.hasAttribute("_uid")) {
                    int uid = uid(e);
                    if (e.getTagName().equals("SubTree") && instanceIds.containsKey(uid + 1)) {
                        e.setAttribute("ID", instanceIds.get(uid + 1));
                    }
                    e.removeAttribute("_uid");
                    e.removeAttribute("_fullpath");
                }
            }
            root.setAttribute("main_tree_to_execute", mainTreeId);
            javax.xml.transform.Transformer out = javax.xml.transform.TransformerFactory.newInstance().newTransformer();
            out.setOutputProperty(javax.xml.transform.OutputKeys.INDENT, "yes");
            java.io.StringWriter text = new java.io.StringWriter();
            out.transform(new javax.xml.transform.dom.DOMSource(root), new javax.xml.transform.stream.StreamResult(text));
            return text.toString();
        } catch (BtlogFormatException | javax.xml.transform.TransformerException e) {
            throw new IllegalStateException("the recorded tree was read, it can be written: " + e.getMessage(), e);
        }
    }

    /** The ID of the tree the recording ran (its first {@code <BehaviorTree>}). */
    public String mainTreeId() {
        return mainTreeId;
    }

    /** The node with this uid, or null. */
    public RecordedNode node(int uid) {
        return byUid.get(uid);
    }

    /** Every node, in uid order. */
    public Map<Integer, RecordedNode> nodes() {
        return Collections.unmodifiableMap(byUid);
    }
}
