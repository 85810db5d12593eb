package org.miron.bt.validation;

import static org.miron.bt.validation.BtIssueCodes.*;

import java.util.List;

import org.eclipse.emf.ecore.EPackage;
import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.EntryUpdatedDecorator;
import org.miron.bt.bt.Loop;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Precondition;
import org.miron.bt.bt.RunOnce;
import org.miron.bt.bt.Script;
import org.miron.bt.bt.ScriptCondition;
import org.miron.bt.bt.Sleep;
import org.miron.bt.bt.Subtree;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.bt.WasEntryUpdated;
import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ParsedScript;
import org.miron.bt.script.ScriptChecks;
import org.miron.bt.script.ScriptSyntaxError;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;

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
        if (node instanceof Script || node instanceof ScriptCondition) {
            checkScript(node, "code", true);
        } else if (node instanceof Precondition) {
            checkScript(node, "if", true);
        }
        for (Attribute attribute : node.getAttributes()) {
            if (BtVersions.SCRIPT_DIRECTIVES.contains(attribute.getName())) {
                checkScript(attribute);
            }
        }
    }

    private void checkScript(TreeNode node, String port, boolean required) {
        Attribute attribute = BtAttributes.find(node.getAttributes(), port);
        if (attribute == null) {
            if (required) {
                error(node.getTag() + " needs attribute " + port, node, BT.getTreeNode_Tag(), MISSING_ATTRIBUTE, port);
            }
            return;
        }
        checkScript(attribute);
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
    public void checkSleep(Sleep node) {
        Attribute msec = BtAttributes.find(node.getAttributes(), "msec");
        if (msec != null && !isBlackboardPointer(msec.getValue()) && !isUnsigned(msec.getValue())) {
            error("msec must be a non-negative integer, not '" + msec.getValue() + "'", msec, BT.getAttribute_Value(),
                    NOT_AN_INTEGER);
        }
    }

    @Check
    public void checkRunOnce(RunOnce node) {
        checkBoolean(node, "then_skip");
    }

    @Check
    public void checkSubtree(Subtree node) {
        if (isV4(node)) {
            checkBoolean(node, "_autoremap");
        }
    }

    @Check
    public void checkEntry(TreeNode node) {
        if (node instanceof WasEntryUpdated || node instanceof EntryUpdatedDecorator) {
            requireAttribute(node, "entry");
        }
    }

    @Check
    public void checkLoop(Loop node) {
        Attribute queue = BtAttributes.find(node.getAttributes(), "queue");
        if (queue == null) {
            requireAttribute(node, "queue");
            return;
        }
        String value = queue.getValue();
        if (isBlackboardPointer(value) || value.isEmpty() || node.getTag().equals("LoopString")) {
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

    private static boolean converts(String element, String tag) {
        switch (tag) {
        case "LoopInt":
            return element.matches("[-+]?\\d+");
        case "LoopDouble":
            return element.matches("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");
        case "LoopBool":
            return BtVersions.BOOLEANS.contains(element);
        default:
            return true;
        }
    }

    private static String typeName(String tag) {
        return tag.equals("LoopInt") ? "an integer" : tag.equals("LoopDouble") ? "a number" : "a boolean";
    }

    /** Version 4 Parallel: success_count and failure_count, optional, counted like the version-3 thresholds. */
    @Check
    public void checkParallel(Parallel node) {
        if (!isV4(node)) {
            return;
        }
        if (node.getTag().equals("ParallelAll")) {
            checkInteger(node, "max_failures");
            return;
        }
        for (String port : List.of("success_count", "failure_count")) {
            Integer value = checkInteger(node, port);
            int children = node.getNodes().size();
            if (value != null && children > 0 && (value > children || value < -children || value == 0)) {
                error(port + " " + value + " does not fit a Parallel with " + children + " children",
                        BtAttributes.find(node.getAttributes(), port), BT.getAttribute_Value(), PARALLEL_THRESHOLD);
            }
        }
    }

    private Integer checkInteger(TreeNode node, String port) {
        Attribute attribute = BtAttributes.find(node.getAttributes(), port);
        if (attribute == null || isBlackboardPointer(attribute.getValue())) {
            return null;
        }
        try {
            return Integer.parseInt(attribute.getValue().trim());
        } catch (NumberFormatException e) {
            error(port + " must be an integer, not '" + attribute.getValue() + "'", attribute, BT.getAttribute_Value(),
                    NOT_AN_INTEGER);
            return null;
        }
    }

    private void checkBoolean(TreeNode node, String port) {
        Attribute attribute = BtAttributes.find(node.getAttributes(), port);
        if (attribute != null && !isBlackboardPointer(attribute.getValue())
                && !BtVersions.BOOLEANS.contains(attribute.getValue())) {
            error(port + " must be true or false, not '" + attribute.getValue() + "'", attribute,
                    BT.getAttribute_Value(), NOT_A_BOOLEAN);
        }
    }

    private void requireAttribute(TreeNode node, String name) {
        if (node.attribute(name) == null) {
            error(node.getTag() + " needs attribute " + name, node, BT.getTreeNode_Tag(), MISSING_ATTRIBUTE, name);
        }
    }

    private static boolean isUnsigned(String value) {
        return value.trim().matches("\\d+");
    }

    private static boolean isBlackboardPointer(String value) {
        String trimmed = value.trim();
        return (trimmed.startsWith("{") || trimmed.startsWith("${")) && trimmed.endsWith("}");
    }
}
