package org.miron.bt.validation;

import static org.miron.bt.validation.BtIssueCodes.*;

import java.util.List;

import org.eclipse.emf.ecore.EPackage;
import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.Loop;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Precondition;
import org.miron.bt.bt.Script;
import org.miron.bt.bt.ScriptCondition;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.BuiltinNodes;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.PortType;
import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ParsedScript;
import org.miron.bt.script.ScriptChecks;
import org.miron.bt.script.ScriptSyntaxError;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.Suggestions;

/**
 * The rules BehaviorTree.CPP 4 applies when it loads a version-4 file: the ports its built-ins
 * require or convert at load time, and the scripts (code, if, _skipIf.._post), parsed and
 * reported at the offending character of the file. Composed into BtValidator.
 */
public class BtV4Validator extends AbstractDeclarativeValidator {

    private static final BtPackage BT = BtPackage.eINSTANCE;

    @Override
    public void register(EValidatorRegistrar registrar) {
        // Runs as part of BtValidator (@ComposedChecks), not on its own.
    }

    @Override
    protected List<EPackage> getEPackages() {
        return List.of(BT);
    }

    private static boolean isV4(TreeNode node) {
        return BtFormats.versionOf(node) == 4;
    }

    /** code of Script and ScriptCondition, if of Precondition, and the pre/post-conditions of any node. */
    @Check
    public void checkScripts(TreeNode node) {
        if (!isV4(node)) {
            return;
        }
        // A missing code or if is BtBuiltinValidator's (a required port in the catalogue).
        if (node instanceof Script || node instanceof ScriptCondition) {
            checkScript(node, BuiltinNodes.CODE);
        } else if (node instanceof Precondition) {
            checkScript(node, BuiltinNodes.IF);
        }
        for (Attribute attribute : node.getAttributes()) {
            if (BtVersions.SCRIPT_DIRECTIVES.contains(attribute.getName())) {
                checkScript(attribute);
            }
        }
    }

    /**
     * An attribute BT.CPP 4 takes for a port remapping while its author meant a pre/post-condition
     * ({@code _onSucess}, {@code _skipif}): the library ignores it silently, so the script never runs.
     */
    @Check
    public void checkConditionNames(TreeNode node) {
        if (!isV4(node)) {
            return;
        }
        for (Attribute attribute : node.getAttributes()) {
            String name = attribute.getName();
            if (name == null || !name.startsWith("_") || BtVersions.SCRIPT_DIRECTIVES.contains(name)
                    || BtVersions.OTHER_UNDERSCORE_ATTRIBUTES.contains(name)) {
                continue;
            }
            List<String> near = Suggestions.closest(name, BtVersions.SCRIPT_DIRECTIVES);
            if (!near.isEmpty()) {
                warning("BehaviorTree.CPP 4 ignores attribute '" + name + "', no pre/post-condition: did you mean '"
                        + near.get(0) + "'?", attribute, BT.getAttribute_Name(), CONDITION_TYPO, near.toArray(new String[0]));
            }
        }
    }

    private void checkScript(TreeNode node, String port) {
        Attribute attribute = BtAttributes.find(node.getAttributes(), port);
        if (attribute != null) {
            checkScript(attribute);
        }
    }

    private void checkScript(Attribute attribute) {
        ParsedScript parsed = BtScripts.parse(attribute.getValue());
        ScriptPositions positions = ScriptPositions.of(attribute);
        for (ScriptSyntaxError syntax : parsed.getErrors()) {
            report("script error in " + attribute.getName() + ": " + syntax.getMessage(), attribute, positions,
                    syntax.getOffset(), syntax.getLength(), SCRIPT_SYNTAX_ERROR);
        }
        for (ScriptChecks.Finding finding : ScriptChecks.check(parsed)) {
            report("script error in " + attribute.getName() + ": " + finding.message, attribute, positions,
                    finding.offset, finding.length, finding.code);
        }
    }

    private void report(String message, Attribute attribute, ScriptPositions positions, int offset, int length,
            String code) {
        if (positions == null) {
            error(message, attribute, BT.getAttribute_Value(), code);
        } else {
            getMessageAcceptor().acceptError(message, attribute, positions.fileOffset(offset),
                    positions.fileLength(offset, length), code);
        }
    }

    @Check
    public void checkLoop(Loop node) {
        Attribute queue = BtAttributes.find(node.getAttributes(), BuiltinNodes.QUEUE);
        if (queue == null || !isV4(node)) {
            return; // missing: BtBuiltinValidator; in version 3 LoopInt is the application's node
        }
        String value = queue.getValue();
        if (BtBuiltinValidator.isBlackboardPointer(value) || value.isEmpty() || node.getTag().equals("LoopString")) {
            return;
        }
        for (String element : value.split(";", -1)) {
            if (!converts(element.trim(), node.getTag())) {
                error(node.getTag() + " queue element '" + element + "' is not " + typeName(node.getTag()), queue,
                        BT.getAttribute_Value(), BAD_LOOP_QUEUE);
                return;
            }
        }
    }

    /** Whether a queue element converts to the type of the loop's value port. */
    private static boolean converts(String element, String tag) {
        return elementType(tag).accepts(element);
    }

    private static PortType elementType(String tag) {
        return NodeCatalogue.require(tag).requirePort(BuiltinNodes.VALUE).type();
    }

    private static String typeName(String tag) {
        return switch (elementType(tag)) {
        case INT -> "an integer";
        case DOUBLE -> "a number";
        default -> "a boolean";
        };
    }

    /** Version 4 Parallel: success_count and failure_count, optional, counted like the version-3 thresholds. */
    @Check
    public void checkParallel(Parallel node) {
        if (!isV4(node) || node.getTag().equals("ParallelAll")) {
            return; // max_failures: an integer (BtBuiltinValidator), any value fits
        }
        for (String port : List.of(BuiltinNodes.SUCCESS_COUNT, BuiltinNodes.FAILURE_COUNT)) {
            Attribute attribute = BtAttributes.find(node.getAttributes(), port);
            Integer value = attribute == null ? null : BtValidator.literalInteger(attribute.getValue());
            int children = node.getNodes().size();
            if (value != null && children > 0 && (value > children || value < -children || value == 0)) {
                error(port + " " + value + " does not fit a Parallel with " + children + " children", attribute,
                        BT.getAttribute_Value(), PARALLEL_THRESHOLD);
            }
        }
    }
}
