package org.miron.bt.nodes;

import java.io.StringReader;
import java.util.LinkedHashMap;
import java.util.Map;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.BTModel;
import org.miron.bt.util.BtTrees;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.InputSource;
import org.xml.sax.helpers.DefaultHandler;

/**
 * The node declarations a BT file sees: those in its own {@code <TreeNodesModel>} and in its
 * includes'. The element is opaque in the model (one token), so it is parsed here as XML; a
 * malformed one declares nothing rather than failing a request.
 */
public final class NodeDeclarations {

    private NodeDeclarations() {
    }

    public static Map<String, NodeDeclaration> visibleFrom(Resource resource) {
        Map<String, NodeDeclaration> result = new LinkedHashMap<>();
        addFrom(resource, result);
        for (Resource included : BtTrees.includedResources(resource)) {
            addFrom(included, result);
        }
        return result;
    }

    private static void addFrom(Resource resource, Map<String, NodeDeclaration> result) {
        if (resource != null && !resource.getContents().isEmpty() && resource.getContents().get(0) instanceof BTModel model
                && model.getNodesmodel() != null) {
            parse(model.getNodesmodel().getContent()).forEach(result::putIfAbsent);
        }
    }

    /** Declarations in the text of a TreeNodesModel element, in document order. */
    public static Map<String, NodeDeclaration> parse(String nodesModel) {
        Map<String, NodeDeclaration> result = new LinkedHashMap<>();
        if (nodesModel == null) {
            return result;
        }
        Element root;
        try {
            root = newBuilder().parse(new InputSource(new StringReader(nodesModel))).getDocumentElement();
        } catch (Exception malformed) {
            return result;
        }
        for (Node child = root.getFirstChild(); child != null; child = child.getNextSibling()) {
            if (child instanceof Element declaration && !declaration.getAttribute("ID").isEmpty()) {
                Map<String, NodeDeclaration.Port> ports = new LinkedHashMap<>();
                for (Node p = declaration.getFirstChild(); p != null; p = p.getNextSibling()) {
                    if (p instanceof Element port && port.getTagName().endsWith("_port") && !port.getAttribute("name").isEmpty()) {
                        String description = port.getTextContent().isBlank() ? port.getAttribute("description")
                                : port.getTextContent().trim();
                        ports.put(port.getAttribute("name"), new NodeDeclaration.Port(port.getAttribute("name"),
                                port.getTagName(), description));
                    }
                }
                result.putIfAbsent(declaration.getAttribute("ID"),
                        new NodeDeclaration(declaration.getAttribute("ID"), declaration.getTagName(), ports));
            }
        }
        return result;
    }

    private static DocumentBuilder newBuilder() throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        // Model files are untrusted input: no DTDs, no external entities.
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        factory.setAttribute(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        factory.setAttribute(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        factory.setExpandEntityReferences(false);
        DocumentBuilder builder = factory.newDocumentBuilder();
        // A half-written <TreeNodesModel> is the parser's business (its diagnostics): the DOM
        // parser's default handler would also print "[Fatal Error] ..." on standard error.
        // DefaultHandler throws on fatal errors and prints nothing.
        builder.setErrorHandler(new DefaultHandler());
        return builder;
    }
}
