package org.miron.cli.monitor;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;

import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * The tree a Groot2 server serves (its FULLTREE XML) placed on the page's tree: each {@code _uid}
 * with the page's node id, the index path from the root with a SubTree call's only child the called
 * tree's root (docs/wire-formats.md, {@code miron.bt.status}), and the names of the subtree
 * instances whose blackboards BLACKBOARD returns. The server writes each subtree instance as its own
 * {@code <BehaviorTree _fullpath>}, created in the order their calls come depth first: a call finds
 * its instance by {@code _fullpath}, else by that order.
 */
final class GrootTreeMap {
    /** One node as the page needs it. */
    record Entry(int uid, String pageId, String name, String type) {
    }

    private final Map<String, Entry> byPageId = new LinkedHashMap<>();
    private final Map<Integer, Entry> byUid = new HashMap<>();
    private final List<String> blackboards = new ArrayList<>();
    private final List<Element> instances = new ArrayList<>();
    private int nextInstance = 1;

    private GrootTreeMap(Document xml) {
        for (Node n = xml.getDocumentElement().getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals("BehaviorTree")) {
                instances.add(e);
            }
        }
        if (instances.isEmpty()) {
            throw new IllegalArgumentException("the tree has no <BehaviorTree>");
        }
        Element main = instances.get(0);
        blackboards.add(main.getAttribute("ID"));
        Element root = firstElement(main);
        if (root == null) {
            throw new IllegalArgumentException("the main tree is empty");
        }
        walk(root, "0");
    }

    /** Reads FULLTREE's XML; an IllegalArgumentException says what is wrong with it. */
    static GrootTreeMap parse(String xml) {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            return new GrootTreeMap(factory.newDocumentBuilder().parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8))));
        } catch (IllegalArgumentException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalArgumentException("the tree is not XML: " + e.getMessage(), e);
        }
    }

    private void walk(Element node, String pageId) {
        String uid = node.getAttribute("_uid");
        if (uid.isEmpty()) {
            throw new IllegalArgumentException("node " + node.getTagName() + " has no _uid");
        }
        boolean call = node.getTagName().equals("SubTree");
        String name = call && !node.hasAttribute("name") ? callName(node) : node.getAttribute("name");
        Entry entry = new Entry(Integer.parseInt(uid), pageId, name.isEmpty() ? node.getTagName() : name, node.getTagName());
        byPageId.put(pageId, entry);
        byUid.put(entry.uid(), entry);
        if (call) {
            Element instance = instance(node.getAttribute("_fullpath"));
            if (instance != null) {
                blackboards.add(instance.getAttribute("_fullpath"));
                Element root = firstElement(instance);
                if (root != null) {
                    walk(root, pageId + ".0");
                }
            }
            return;
        }
        int i = 0;
        for (Node n = node.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element child) {
                walk(child, pageId + "." + i++);
            }
        }
    }

    /**
     * A SubTree call's name: the library writes none, but its {@code _fullpath} ends with it
     * ({@code parent/name}), or with {@code ID::uid} when the call has no name.
     */
    private static String callName(Element call) {
        String path = call.getAttribute("_fullpath");
        String last = path.substring(path.lastIndexOf('/') + 1);
        return last.isEmpty() || last.contains("::") ? call.getAttribute("ID") : last;
    }

    private Element instance(String fullPath) {
        for (int i = 1; i < instances.size(); i++) {
            if (instances.get(i).getAttribute("_fullpath").equals(fullPath)) {
                nextInstance = i + 1;
                return instances.get(i);
            }
        }
        return nextInstance < instances.size() ? instances.get(nextInstance++) : null;
    }

    private static Element firstElement(Element parent) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e) {
                return e;
            }
        }
        return null;
    }

    /** The node with this page id, or null. */
    Entry byPageId(String pageId) {
        return byPageId.get(pageId);
    }

    /** The node with this uid, or null. */
    Entry byUid(int uid) {
        return byUid.get(uid);
    }

    /** The root's uid: a step pauses before its next tick. */
    int rootUid() {
        return byPageId.get("0").uid();
    }

    int size() {
        return byUid.size();
    }

    /** The subtree instances' names as BLACKBOARD asks for them (the main tree by its ID). */
    List<String> blackboards() {
        return Collections.unmodifiableList(blackboards);
    }
}
