package org.miron.bt.formats;

import java.util.List;
import java.util.regex.Pattern;

import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ParsedScript;
import org.miron.bt.script.ast.Comparison;
import org.miron.bt.script.ast.ComparisonOperator;
import org.miron.bt.script.ast.Expression;
import org.miron.bt.script.ast.Name;
import org.miron.bt.script.ast.NumberLiteral;
import org.miron.bt.script.ast.StringLiteral;
import org.miron.bt.script.ast.Unary;
import org.miron.bt.script.ast.UnaryOperator;

/**
 * BT.CPP 3's BlackboardCheckInt/Double/String(value_A, value_B, return_on_mismatch) is BT.CPP 4's
 * {@code <Precondition if="A == B" else="return_on_mismatch">}: a {key} operand becomes the name
 * key, a literal stays a literal of the check's type (an Int or Double literal as written, a String
 * literal quoted), so the type can be read back from the literal.
 */
final class BlackboardChecks {
    private static final Pattern NAME = Pattern.compile("@?[A-Za-z_][A-Za-z0-9_]*");
    private static final Pattern INTEGER = Pattern.compile("-?\\d+");
    private static final Pattern REAL = Pattern.compile("-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?");

    /** What a v4 condition reads back as: a BlackboardCheck tag and its two values. */
    static final class Check {
        final String tag;
        final String valueA;
        final String valueB;

        Check(String tag, String valueA, String valueB) {
            this.tag = tag;
            this.valueA = valueA;
            this.valueB = valueB;
        }
    }

    private BlackboardChecks() {
    }

    /** The script operand for a check's value, or null when the script cannot express it. */
    static String operand(String tag, String value) {
        if (TreeEdits.isRemap(value)) {
            String key = value.substring(1, value.length() - 1);
            return NAME.matcher(key).matches() ? key : null;
        }
        switch (tag) {
        case "BlackboardCheckInt":
            return INTEGER.matcher(value).matches() ? value : null;
        case "BlackboardCheckDouble":
            return REAL.matcher(value).matches() ? value : null;
        default:
            if (value.indexOf('\'') < 0) {
                return "'" + value + "'";
            }
            return value.indexOf('"') < 0 ? "\"" + value + "\"" : null;
        }
    }

    /** The BlackboardCheck a Precondition condition reads as, or null unless it is {@code A == B} of names and literals. */
    static Check fromCondition(String condition) {
        ParsedScript parsed = BtScripts.parse(condition);
        List<Expression> statements = parsed.getScript().getStatements();
        if (parsed.hasErrors() || statements.size() != 1 || !(statements.get(0) instanceof Comparison)) {
            return null;
        }
        Comparison comparison = (Comparison) statements.get(0);
        if (comparison.getOperands().size() != 2 || comparison.getOperators().get(0) != ComparisonOperator.EQUAL) {
            return null;
        }
        String a = value(comparison.getOperands().get(0));
        String b = value(comparison.getOperands().get(1));
        if (a == null || b == null) {
            return null;
        }
        return new Check(type(comparison), a, b);
    }

    private static String type(Comparison comparison) {
        boolean real = false;
        boolean integer = false;
        for (Expression operand : comparison.getOperands()) {
            if (operand instanceof StringLiteral) {
                return "BlackboardCheckString";
            }
            NumberLiteral number = number(operand);
            if (number != null) {
                real |= number.isReal();
                integer |= !number.isReal();
            }
        }
        // Two keys compare as the text BT.CPP 3 reads from the blackboard.
        return real ? "BlackboardCheckDouble" : integer ? "BlackboardCheckInt" : "BlackboardCheckString";
    }

    private static String value(Expression operand) {
        if (operand instanceof Name) {
            return "{" + ((Name) operand).getName() + "}";
        }
        if (operand instanceof StringLiteral) {
            return ((StringLiteral) operand).getValue();
        }
        NumberLiteral number = number(operand);
        if (number == null || number.getText().toLowerCase().startsWith("0x") || number.getText().startsWith("+")) {
            return null;
        }
        return (operand instanceof Unary ? "-" : "") + number.getText();
    }

    /** A number literal, or a negated one (BT.CPP 3 values carry their sign). */
    private static NumberLiteral number(Expression operand) {
        if (operand instanceof NumberLiteral) {
            return (NumberLiteral) operand;
        }
        if (operand instanceof Unary && ((Unary) operand).getOperator() == UnaryOperator.NEGATE
                && ((Unary) operand).getOperand() instanceof NumberLiteral) {
            return (NumberLiteral) ((Unary) operand).getOperand();
        }
        return null;
    }
}
