package org.miron.dsl.bt;

import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPathConstants;
import javax.xml.xpath.XPathExpression;
import javax.xml.xpath.XPathExpressionException;
import javax.xml.xpath.XPathFactory;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.TreeNode;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * Evaluates a BtBinding's XPath on the XML of the .bt file that holds a target node, with that
 * node's element as context node (so "@speed" and ".//Action" are relative to it, "//Action" is
 * not), and maps what it selects back to the BT model. Elements and model objects correspond by
 * position: the n-th BehaviorTree element is the n-th tree, and a node's n-th child element is its
 * n-th child node, which is how the BT grammar builds the model.
 */
public final class BtXPath {

    /** One selected XML node and the BT model object it stands for (null when there is none). */
    public static final class Selection {
        public final Node dom;
        public final EObject model;

        Selection(Node dom, EObject model) {
            this.dom = dom;
            this.model = model;
        }

        public boolean isAttribute() {
            return dom.getNodeType() == Node.ATTRIBUTE_NODE;
        }

        public boolean isTreeNode() {
            return model instanceof TreeNode;
        }

        /** As a user would name it in a message: &lt;Action ID="x"&gt;, @speed of &lt;GoTo&gt;... */
        public String describe() {
            if (isAttribute()) {
                Element owner = ((org.w3c.dom.Attr) dom).getOwnerElement();
                return "attribute @" + dom.getNodeName() + " of <" + owner.getTagName() + ">";
            } else if (dom.getNodeType() == Node.ELEMENT_NODE) {
                Element e = (Element) dom;
                String id = e.getAttribute("ID");
                String name = e.getAttribute("name");
                return "<" + e.getTagName() + (id.isEmpty() ? "" : " ID=\"" + id + "\"")
                        + (name.isEmpty() ? "" : " name=\"" + name + "\"") + ">";
            }
            return dom.getNodeName();
        }
    }

    /** The outcome: either selections or an error message. */
    public static final class Result {
        public final List<Selection> selections = new ArrayList<>();
        public String error;
    }

    private BtXPath() {
    }

    public static Result evaluate(String xpath, TreeNode target) {
        Result result = new Result();
        Resource resource = target.eResource();
        if (resource == null || resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof BTModel)) {
            result.error = "the target node is not in a loaded .bt file";
            return result;
        }
        Document doc;
        try {
            doc = parse(resource);
        } catch (Exception e) {
            result.error = "cannot read " + resource.getURI().lastSegment() + " as XML: " + e.getMessage();
            return result;
        }
        BTModel model = (BTModel) resource.getContents().get(0);
        Element context = domOf(target, model, doc);
        if (context == null) {
            result.error = "cannot locate the target node in " + resource.getURI().lastSegment();
            return result;
        }
        XPathExpression compiled;
        try {
            compiled = XPathFactory.newInstance().newXPath().compile(xpath);
        } catch (XPathExpressionException e) {
            Throwable cause = e.getCause() != null ? e.getCause() : e;
            result.error = "invalid XPath '" + xpath + "': " + cause.getMessage();
            return result;
        }
        NodeList nodes;
        try {
            nodes = (NodeList) compiled.evaluate(context, XPathConstants.NODESET);
        } catch (XPathExpressionException e) {
            // count(...), string(...) and the like compute a value instead of selecting nodes
            result.error = "invalid XPath '" + xpath + "': it must select nodes or attributes, not compute a value";
            return result;
        }
        for (int i = 0; i < nodes.getLength(); i++) {
            Node n = nodes.item(i);
            result.selections.add(new Selection(n, modelOf(n, model, doc)));
        }
        return result;
    }

    private static Document parse(Resource resource) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        // BT files never need a DTD: refuse them rather than fetch anything.
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        factory.setAttribute(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        factory.setExpandEntityReferences(false);
        DocumentBuilder builder = factory.newDocumentBuilder();
        builder.setErrorHandler(null);
        try (InputStream in = resource.getResourceSet().getURIConverter().createInputStream(resource.getURI())) {
            return builder.parse(in);
        }
    }

    private static List<Element> childElements(Node parent, String onlyTag) {
        List<Element> result = new ArrayList<>();
        for (Node c = parent.getFirstChild(); c != null; c = c.getNextSibling()) {
            if (c.getNodeType() == Node.ELEMENT_NODE && (onlyTag == null || onlyTag.equals(c.getNodeName()))) {
                result.add((Element) c);
            }
        }
        return result;
    }

    /** Children of a model object in document order. */
    private static List<? extends EObject> modelChildren(EObject obj) {
        if (obj instanceof BehaviorTree) {
            return ((BehaviorTree) obj).getNodes();
        } else if (obj instanceof ControlNode) {
            return ((ControlNode) obj).getNodes();
        } else if (obj instanceof DecoratorNode) {
            DecoratorNode d = (DecoratorNode) obj;
            List<TreeNode> all = new ArrayList<>();
            if (d.getNode() != null) {
                all.add(d.getNode());
            }
            all.addAll(d.getSurplus());
            return all;
        }
        return List.of();
    }

    /** The XML element of a tree node, by walking the same child positions in both trees. */
    static Element domOf(TreeNode node, BTModel model, Document doc) {
        List<Integer> path = new ArrayList<>();
        EObject current = node;
        while (!(current instanceof BehaviorTree)) {
            EObject parent = current.eContainer();
            if (parent == null) {
                return null;
            }
            path.add(0, modelChildren(parent).indexOf(current));
            current = parent;
        }
        int tree = model.getTrees().indexOf(current);
        List<Element> trees = childElements(doc.getDocumentElement(), "BehaviorTree");
        if (tree < 0 || tree >= trees.size()) {
            return null;
        }
        Element e = trees.get(tree);
        for (int index : path) {
            List<Element> children = childElements(e, null);
            if (index < 0 || index >= children.size()) {
                return null;
            }
            e = children.get(index);
        }
        return e;
    }

    /** The model object standing for a selected XML node, or null (e.g. the TreeNodesModel). */
    static EObject modelOf(Node n, BTModel model, Document doc) {
        if (n.getNodeType() == Node.ATTRIBUTE_NODE) {
            EObject owner = modelOf(((org.w3c.dom.Attr) n).getOwnerElement(), model, doc);
            List<Attribute> attributes = owner instanceof TreeNode ? ((TreeNode) owner).getAttributes()
                    : owner instanceof BehaviorTree ? ((BehaviorTree) owner).getAttributes()
                    : owner instanceof BTModel ? ((BTModel) owner).getAttributes() : List.of();
            for (Attribute a : attributes) {
                if (n.getNodeName().equals(a.getName())) {
                    return a;
                }
            }
            return null;
        }
        if (n == doc.getDocumentElement()) {
            return model;
        }
        if (n.getNodeType() != Node.ELEMENT_NODE) {
            return null;
        }
        List<Integer> path = new ArrayList<>();
        Node current = n;
        while (current.getParentNode() != null && current.getParentNode() != doc.getDocumentElement()) {
            if (current.getParentNode().getNodeType() != Node.ELEMENT_NODE) {
                return null;
            }
            path.add(0, childElements(current.getParentNode(), null).indexOf(current));
            current = current.getParentNode();
        }
        if (current == doc.getDocumentElement()) {
            return model;
        }
        if (!"BehaviorTree".equals(current.getNodeName())) {
            return null;
        }
        int tree = childElements(doc.getDocumentElement(), "BehaviorTree").indexOf(current);
        if (tree < 0 || tree >= model.getTrees().size()) {
            return null;
        }
        EObject obj = model.getTrees().get(tree);
        for (int index : path) {
            List<? extends EObject> children = modelChildren(obj);
            if (index < 0 || index >= children.size()) {
                return null;
            }
            obj = children.get(index);
        }
        return obj;
    }
}
