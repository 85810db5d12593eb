package org.miron.dsl.ide.hover;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.ide.hover.BtDocumentationProvider;
import org.miron.dsl.miron.BehaviorTreeEnumType;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.NumericSampledType;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.DocumentableElement;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.RoqmePackage;

/**
 * Hover text of RoQME and MIRoN elements (markdown): the documentation comment, the declaration,
 * for a varpoint each value with its impacts, and for observations and beliefs what the RoQME
 * reasoner makes of them (EvidenceHover). Imported BT elements are described as the BT
 * language does.
 */
public class DslDocumentationProvider implements IEObjectDocumentationProvider {

    @Override
    public String getDocumentation(EObject element) {
        if (element.eClass().getEPackage() == BtPackage.eINSTANCE) {
            return BtDocumentationProvider.documentation(element);
        }
        List<String> parts = new ArrayList<>();
        if (element instanceof DocumentableElement documented && documented.getDocumentation() != null) {
            parts.add(comment(documented.getDocumentation()));
        }
        if (element instanceof FunctionCall call && RoqmeFunctions.describe(call.getFunction()) != null) {
            parts.add(RoqmeFunctions.describe(call.getFunction()));
        }
        if (element instanceof TemporalExpression temporal) {
            parts.add(TemporalOperators.describe(temporal)); // the keyword's meaning, not the whole formula
        } else if (element instanceof Requirement requirement) {
            parts.add(TemporalOperators.describe(requirement));
        } else if (element instanceof VariationPoint varpoint) {
            parts.add(values(varpoint));
        } else if (element.eClass().getEPackage() == RoqmePackage.eINSTANCE
                || element.eClass().getEPackage() == MironPackage.eINSTANCE) {
            String declaration = sourceText(element);
            if (declaration != null) {
                parts.add("```\n" + declaration + "\n```");
            }
            if (element instanceof Observation observation) {
                parts.add(EvidenceHover.observation(observation));
            } else if (element instanceof BeliefVariable belief) {
                parts.add(EvidenceHover.belief(belief));
            }
        }
        return parts.isEmpty() ? null : String.join("\n\n", parts);
    }

    /** The varpoint's values (variants or samples), each with its impacts, and its binding. */
    private static String values(VariationPoint varpoint) {
        StringBuilder text = new StringBuilder("**varpoint " + varpoint.getName() + "**");
        List<? extends EObject> values = varpoint.getDeclaration() instanceof BehaviorTreeEnumType type ? type.getLiterals()
                : varpoint.getDeclaration() instanceof NumericSampledType type ? type.getSamples() : List.of();
        if (values.isEmpty()) {
            String declaration = sourceText(varpoint.getDeclaration());
            if (declaration != null) {
                text.append(": `").append(declaration).append('`');
            }
        } else {
            text.append(", values:\n");
            for (EObject value : values) {
                text.append("\n- `").append(sourceText(value)).append('`');
            }
        }
        if (varpoint.getBinding() != null) {
            text.append("\n\nbound to `").append(sourceText(varpoint.getBinding())).append('`');
        }
        return text.toString();
    }

    /** An element's documentation comment as plain text, or null. */
    public static String plainDocumentation(EObject element) {
        return element instanceof DocumentableElement documented && documented.getDocumentation() != null
                ? comment(documented.getDocumentation())
                : null;
    }

    private static String comment(String documentation) {
        String text = documentation.strip();
        if (text.startsWith("/**") && text.endsWith("*/")) {
            text = text.substring(3, text.length() - 2);
        }
        return text.replaceAll("(?m)^\\s*\\*\\s?", "").strip();
    }

    /** An element's text with its layout reduced to single spaces, without its documentation comment. */
    static String sourceText(EObject element) {
        ICompositeNode node = element == null ? null : NodeModelUtils.findActualNodeFor(element);
        if (node == null) {
            return null;
        }
        String text = NodeModelUtils.getTokenText(node);
        if (text.startsWith("/**")) {
            int end = text.indexOf("*/");
            text = end < 0 ? text : text.substring(end + 2).strip();
        }
        return text;
    }
}
