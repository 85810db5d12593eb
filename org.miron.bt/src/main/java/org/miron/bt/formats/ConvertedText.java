package org.miron.bt.formats;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;

/**
 * Writes a converted file as edits of its own text, so that what the conversion does not touch
 * stays as it was: comments, blank lines, attribute layout, the XML declaration. Before the
 * conversion it notes where each element's start tag, tag name, attributes and end tag are; after
 * it, each element whose tag or attributes changed gets its start tag (and end-tag name) rewritten
 * in place. The result is parsed again and must give the converted model; if it does not (an edit
 * this class does not know how to write), the caller prints the model instead.
 */
final class ConvertedText {
    /** Where one element's parts are in the original text. */
    private record Element(String tag, int tagOffset, int tagLength, int endTagNameOffset,
            List<Attribute> attributes, Map<Attribute, String> written, int lastItemEnd, boolean hasId) {
    }

    private final XtextResource resource;
    private final String original;
    private final Map<EObject, Element> elements = new IdentityHashMap<>();
    private final Map<Attribute, int[]> attributeRegions = new IdentityHashMap<>();

    /** Notes the elements of the parsed, not yet converted model. */
    ConvertedText(XtextResource resource) {
        this.resource = resource;
        this.original = resource.getParseResult().getRootNode().getText();
        BTModel model = (BTModel) resource.getContents().get(0);
        note(model, model.getAttributes());
        model.eAllContents().forEachRemaining(o -> {
            if (o instanceof TreeNode node) {
                note(node, node.getAttributes());
            }
        });
    }

    private void note(EObject object, List<Attribute> attributes) {
        ICompositeNode node = NodeModelUtils.getNode(object);
        if (node == null) {
            return;
        }
        List<ILeafNode> leaves = new ArrayList<>();
        for (ILeafNode leaf : node.getLeafNodes()) {
            if (!leaf.isHidden()) {
                leaves.add(leaf);
            }
        }
        // '<' name ... ('>' | '/>'): the first closing keyword ends the start tag (values are strings)
        if (leaves.size() < 3 || !"<".equals(leaves.get(0).getText())) {
            return;
        }
        int close = -1;
        for (int i = 2; i < leaves.size(); i++) {
            String text = leaves.get(i).getText();
            if (leaves.get(i).getGrammarElement() instanceof Keyword && (text.equals(">") || text.equals("/>"))) {
                close = i;
                break;
            }
        }
        if (close < 0) {
            return;
        }
        ILeafNode name = leaves.get(1);
        int lastItemEnd = name.getEndOffset();
        Map<Attribute, String> written = new IdentityHashMap<>();
        for (Attribute attribute : attributes) {
            INode actual = NodeModelUtils.findActualNodeFor(attribute);
            if (actual != null) {
                attributeRegions.put(attribute, new int[] { actual.getOffset(), actual.getEndOffset() });
                written.put(attribute, attribute.getName() + "\u0000" + attribute.getValue());
            }
        }
        boolean hasId = false;
        for (int i = 2; i < close; i++) {
            lastItemEnd = Math.max(lastItemEnd, leaves.get(i).getEndOffset());
            hasId |= leaves.get(i).getText().equals("ID");
        }
        int endTagName = -1;
        if (leaves.get(close).getText().equals(">") && leaves.size() >= close + 3
                && leaves.get(leaves.size() - 3).getText().equals("</")) {
            endTagName = leaves.get(leaves.size() - 2).getOffset();
        }
        elements.put(object, new Element(name.getText(), name.getOffset(), name.getLength(), endTagName,
                List.copyOf(attributes), written, lastItemEnd, hasId));
    }

    /** The converted model's text, or null when the edits cannot express the conversion. */
    String write(Conversion conversion) {
        BTModel model = (BTModel) resource.getContents().get(0);
        IValueConverterService values = resource.getResourceServiceProvider().get(IValueConverterService.class);
        List<int[]> regions = new ArrayList<>(); // offset, end, index into texts
        List<String> texts = new ArrayList<>();
        for (Map.Entry<EObject, Element> entry : elements.entrySet()) {
            EObject now = conversion.getReplacements().getOrDefault(entry.getKey(), entry.getKey());
            Element was = entry.getValue();
            String tag = now instanceof TreeNode node ? node.getTag() : was.tag();
            List<Attribute> attributes = now instanceof TreeNode node ? node.getAttributes()
                    : now instanceof BTModel root ? root.getAttributes() : was.attributes();
            if (!tag.equals(was.tag())) {
                // a tree used as an element name (<GoTo/>) becomes <SubTree ID="GoTo"/>
                String id = now instanceof SubtreeNode && !was.hasId() ? " ID=" + values.toString(was.tag(), "STRING") : "";
                edit(regions, texts, was.tagOffset(), was.tagOffset() + was.tagLength(), tag + id);
                if (was.endTagNameOffset() >= 0) {
                    edit(regions, texts, was.endTagNameOffset(), was.endTagNameOffset() + was.tag().length(), tag);
                }
            }
            for (Attribute old : was.attributes()) {
                int[] region = attributeRegions.get(old);
                if (region == null) {
                    return null;
                }
                if (!attributes.contains(old)) { // removed, with the space before it
                    int from = region[0];
                    while (from > 0 && Character.isWhitespace(original.charAt(from - 1))) {
                        from--;
                    }
                    edit(regions, texts, from, region[1], "");
                } else if (!was.written().get(old).equals(old.getName() + "\u0000" + old.getValue())) {
                    edit(regions, texts, region[0], region[1], write(old, values));
                }
            }
            StringBuilder added = new StringBuilder();
            for (Attribute attribute : attributes) {
                if (!was.attributes().contains(attribute)) {
                    added.append(' ').append(write(attribute, values));
                }
            }
            if (added.length() > 0) {
                // BTCPP_format goes first on <root>; elsewhere new attributes follow the written ones
                int at = now instanceof BTModel ? was.tagOffset() + was.tagLength() : was.lastItemEnd();
                edit(regions, texts, at, at, added.toString());
            }
        }
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < regions.size(); i++) {
            order.add(i);
        }
        order.sort((a, b) -> regions.get(b)[0] != regions.get(a)[0] ? Integer.compare(regions.get(b)[0], regions.get(a)[0])
                : Integer.compare(regions.get(b)[1], regions.get(a)[1]));
        StringBuilder text = new StringBuilder(original);
        int limit = Integer.MAX_VALUE;
        for (int i : order) {
            int[] r = regions.get(i);
            if (r[1] > limit) {
                return null; // overlapping edits: not expressible here
            }
            text.replace(r[0], r[1], texts.get(i));
            limit = r[0];
        }
        return sameModel(model, text.toString()) ? text.toString() : null;
    }

    private static void edit(List<int[]> regions, List<String> texts, int from, int to, String text) {
        regions.add(new int[] { from, to });
        texts.add(text);
    }

    private static String write(Attribute attribute, IValueConverterService values) {
        return attribute.getName() + "=" + values.toString(attribute.getValue(), "STRING");
    }

    /** Parses the text next to the file, in its resource set (includes resolve alike), and compares. */
    private boolean sameModel(BTModel converted, String text) {
        ResourceSet set = resource.getResourceSet();
        URI uri = resource.getURI().trimFileExtension().appendFileExtension("converted")
                .appendFileExtension(resource.getURI().fileExtension());
        Resource again = set.createResource(uri);
        try {
            again.load(new java.io.ByteArrayInputStream(text.getBytes(java.nio.charset.StandardCharsets.UTF_8)), null);
            return again.getErrors().isEmpty() && !again.getContents().isEmpty()
                    && EcoreUtil.equals(converted, again.getContents().get(0));
        } catch (java.io.IOException e) {
            return false;
        } finally {
            again.unload();
            set.getResources().remove(again);
        }
    }
}
