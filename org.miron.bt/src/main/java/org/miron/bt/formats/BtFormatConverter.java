package org.miron.bt.formats;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.formatting2.BtFormatting;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;

/**
 * Converts a BT model between the XML formats of BehaviorTree.CPP 3 and 4, in place (write it
 * with {@link #text}). Version 3 to 4 follows BehaviorTree.CPP's convert_v3_to_v4.py and
 * adds what it leaves out (V3ToV4); version 4 to 3 converts what has an equivalent and otherwise
 * changes nothing and reports every element that has none (V4ToV3).
 *
 * <p>A round trip 3 → 4 → 3 gives the same model, except where BehaviorTree.CPP 4 merged two
 * version-3 spellings: RetryUntilSuccesful comes back as RetryUntilSuccessful,
 * {@code <SubTree __shared_blackboard="true">} as {@code <SubTreePlus __autoremap="true">} (v4's
 * _autoremap is SubTreePlus's remapping), and meaningless {@code __shared_blackboard="false"}
 * attributes are dropped.
 */
public final class BtFormatConverter {
    private static final Pattern PROLOG = Pattern.compile("\\s*(<\\?xml[^>]*\\?>)");

    private BtFormatConverter() {
    }

    /** Converts to {@code targetVersion} (3 or 4); a file already in that version is left as it is. */
    public static Conversion convert(BTModel model, int targetVersion) {
        if (targetVersion != 3 && targetVersion != 4) {
            throw new IllegalArgumentException("BehaviorTree.CPP format " + targetVersion + " (3 or 4)");
        }
        if (BtFormats.version(model) == targetVersion) {
            return new Conversion(List.of(), Map.of());
        }
        List<TreeNode> nodes = new ArrayList<>();
        for (EObject object : (Iterable<EObject>) () -> EcoreUtil.getAllContents(model, true)) {
            if (object instanceof TreeNode) {
                nodes.add((TreeNode) object);
            }
        }
        List<ConversionProblem> problems = new ArrayList<>();
        for (TreeNode node : nodes) {
            if (targetVersion == 4) {
                V3ToV4.check(node, problems);
            } else {
                V4ToV3.check(node, problems);
            }
        }
        if (!problems.isEmpty()) {
            return new Conversion(problems, Map.of());
        }
        Map<EObject, EObject> replacements = new HashMap<>();
        for (TreeNode node : nodes) {
            if (targetVersion == 4) {
                V3ToV4.apply(node, replacements);
            } else {
                V4ToV3.apply(node, replacements);
            }
        }
        setFormat(model, targetVersion);
        return new Conversion(List.of(), replacements);
    }

    /** A converted file: what the conversion found, and when it succeeded the file's new text (else null). */
    public record ConvertedFile(Conversion conversion, String text) {
    }

    /**
     * Converts a parsed file and writes it back as text, keeping everything the conversion does not
     * touch as it was: comments, blank lines, attribute layout, the XML declaration. Only changed
     * start tags, end-tag names and attributes are rewritten (ConvertedText); where that cannot
     * express a change, the whole model is printed as {@link #text} does. Converts the resource's
     * model in place, like {@link #convert}.
     */
    public static ConvertedFile convertFile(XtextResource resource, int targetVersion) {
        ConvertedText edits = new ConvertedText(resource);
        BTModel model = (BTModel) resource.getContents().get(0);
        Conversion conversion = convert(model, targetVersion);
        if (!conversion.succeeded()) {
            return new ConvertedFile(conversion, null);
        }
        String text = edits.write(conversion);
        return new ConvertedFile(conversion, text != null ? text : text(model));
    }

    /**
     * The converted model as a file: the source's XML declaration, then the model printed by the
     * BT formatter. Comments of the source are not kept (the serializer writes the model): to keep
     * them, convert with {@link #convertFile}.
     */
    public static String text(BTModel model) {
        String printed = BtFormatting.print(model).replaceAll("^\\s+", "");
        // Where comments were, the serializer leaves empty lines: drop lines holding only spaces.
        printed = printed.replaceAll("\n[ \t]*(?=\n)", "");
        ICompositeNode node = NodeModelUtils.getNode(model);
        Matcher prolog = PROLOG.matcher(node == null ? "" : node.getRootNode().getText());
        return prolog.lookingAt() ? prolog.group(1) + "\n" + printed : printed;
    }

    /** BTCPP_format="4" first on the root; version 3 files have none. */
    private static void setFormat(BTModel model, int version) {
        Attribute format = BtAttributes.find(model.getAttributes(), BtFormats.ATTRIBUTE);
        if (version == 3) {
            model.getAttributes().remove(format);
        } else if (format == null) {
            model.getAttributes().add(0, TreeEdits.attribute(BtFormats.ATTRIBUTE, "4"));
        } else {
            format.setValue("4");
        }
    }
}
