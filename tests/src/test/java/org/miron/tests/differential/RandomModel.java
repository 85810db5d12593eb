package org.miron.tests.differential;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/**
 * A random, valid MIRoN model (text) for the differential test: properties and contexts (number,
 * boolean, enum) declared in the model itself, enum (with tree literals, presets, impacts), numeric (with
 * sampled impacts) and boolean varpoints, and rules whose conditions read metrics, contexts and
 * varpoints and whose consequences constrain one or several varpoints (coupling them).
 */
final class RandomModel {
    /** The behaviour trees the enum literals refer to (written next to the model as t.bt). */
    static final String BT = """
            <root main_tree_to_execute="Main">
              <BehaviorTree ID="Main"><Action ID="A" name="a"/></BehaviorTree>
              <BehaviorTree ID="T0"><Action ID="A"/></BehaviorTree>
              <BehaviorTree ID="T1"><Action ID="A"/></BehaviorTree>
              <BehaviorTree ID="T2"><Action ID="A"/></BehaviorTree>
              <BehaviorTree ID="T3"><Action ID="A"/></BehaviorTree>
            </root>
            """;
    private static final String[] INTENSITIES = {"+++", "++", "+", "-", "--", "---"};
    private static final String[] RANGES = {"(0:0.5:3)", "(1:5)", "(0:1:10)", "(-2:0.25:2)", "(0:0.1:1)", "(10:10:100)"};
    private static final double[][] RANGE_BOUNDS = {{0, 3}, {1, 5}, {0, 10}, {-2, 2}, {0, 1}, {10, 100}};
    private static final double[] STEPS = {0.5, 0.02, 1, 0.25, 0.1, 10};
    private static final String[] COMPARISONS = {"<", "<=", ">", ">="};

    private final Random random;
    private final StringBuilder text = new StringBuilder("import \"t.bt\" as bt\n");
    private final int properties;
    /** Per varpoint: 'e' enum (with its literal count), 'n' number (with its range), 'b' boolean. */
    private final List<char[]> kinds = new ArrayList<>();
    private final List<Integer> sizes = new ArrayList<>();
    /** Few varpoints and many rules that often apply: rules that cannot all hold (priority decides). */
    private final boolean conflicting;

    private RandomModel(Random random, boolean conflicting) {
        this.random = random;
        this.conflicting = conflicting;
        properties = 1 + random.nextInt(3);
    }

    static String generate(Random random) {
        return new RandomModel(random, false).build();
    }

    /** A model whose rules often conflict: 1 or 2 varpoints, 3 to 6 rules. */
    static String generateConflicting(Random random) {
        return new RandomModel(random, true).build();
    }

    private String build() {
        for (int p = 0; p < properties; p++) {
            text.append("property p").append(p).append(random.nextBoolean() ? " reference 0." + (1 + random.nextInt(9)) : "")
                    .append('\n');
        }
        text.append("context c0 : number (0:10)\ncontext c1 : number (-5:5)\ncontext b0 : boolean\n")
                .append("context e0 : enum { A, B, C }\n");
        int varpoints = conflicting ? 1 + random.nextInt(2) : 1 + random.nextInt(4);
        for (int v = 0; v < varpoints; v++) {
            varpoint(v);
        }
        int rules = conflicting ? 3 + random.nextInt(4) : random.nextInt(6);
        for (int r = 0; r < rules; r++) {
            text.append("rule r").append(r).append(" : ");
            if (random.nextInt(5) > 0) {
                text.append(conflicting ? condition(0) : condition(2)).append(' ');
            }
            text.append("implies ");
            int consequences = 1 + random.nextInt(2);
            if (consequences == 1) {
                text.append(consequence()).append('\n');
            } else {
                text.append("{ ").append(consequence()).append(", ").append(consequence()).append(" }\n");
            }
        }
        return text.toString();
    }

    private void varpoint(int v) {
        int kind = random.nextInt(5);
        text.append("@varpoint v").append(v).append(" : ");
        if (kind <= 1) {
            int n = 2 + random.nextInt(3);
            int preset = random.nextInt(n); // a tree enum needs exactly one preset
            text.append("enum { ");
            for (int i = 0; i < n; i++) {
                text.append(i == 0 ? "" : ", ").append('x').append(i).append(" : ")
                        .append(i == preset ? "preset" : "bt.T" + (i % 4));
                if (random.nextInt(3) > 0) {
                    text.append(" affects ").append(impacts());
                }
            }
            text.append(" }\n");
            kinds.add(new char[] {'e'});
            sizes.add(n);
        } else if (kind <= 3) {
            int range = random.nextInt(RANGES.length);
            text.append("number ").append(RANGES[range]);
            double lo = RANGE_BOUNDS[range][0], hi = RANGE_BOUNDS[range][1];
            int samples = random.nextInt(4);
            List<Double> seen = new ArrayList<>();
            StringBuilder s = new StringBuilder();
            for (int i = 0; i < samples; i++) {
                int steps = (int) Math.round((hi - lo) / STEPS[range]);
                double x = java.math.BigDecimal.valueOf(lo).add(java.math.BigDecimal.valueOf(STEPS[range])
                        .multiply(java.math.BigDecimal.valueOf(random.nextInt(steps + 1)))).doubleValue();
                if (seen.contains(x)) {
                    continue;
                }
                seen.add(x);
                s.append(s.length() == 0 ? "" : ", ").append(number(x)).append(" affects ").append(impacts());
            }
            if (s.length() > 0) {
                text.append(" { ").append(s).append(" }");
            }
            text.append('\n');
            kinds.add(new char[] {'n', (char) range});
            sizes.add(0);
        } else {
            text.append("boolean\n");
            kinds.add(new char[] {'b'});
            sizes.add(2);
        }
    }

    private double onGrid(int range) {
        double lo = RANGE_BOUNDS[range][0], hi = RANGE_BOUNDS[range][1];
        int steps = (int) Math.round((hi - lo) / STEPS[range]);
        return java.math.BigDecimal.valueOf(lo).add(java.math.BigDecimal.valueOf(STEPS[range])
                .multiply(java.math.BigDecimal.valueOf(random.nextInt(steps + 1)))).doubleValue();
    }

    private String impacts() {
        int n = 1 + random.nextInt(properties);
        StringBuilder b = new StringBuilder(n > 1 ? "{ " : "");
        List<Integer> used = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int p = random.nextInt(properties);
            if (used.contains(p)) {
                continue;
            }
            used.add(p);
            b.append(used.size() > 1 ? ", " : "").append('p').append(p)
                    .append(INTENSITIES[random.nextInt(INTENSITIES.length)]);
        }
        return b.append(n > 1 ? " }" : "").toString();
    }

    private String condition(int depth) {
        int pick = random.nextInt(depth > 0 ? 10 : 7);
        switch (pick) {
            case 0:
                return "p" + random.nextInt(properties) + " " + cmp() + " " + number(random.nextInt(11) / 10.0);
            case 1:
                return "c0 " + cmp() + " " + number(random.nextInt(21) / 2.0);
            case 2:
                return random.nextBoolean() ? "b0" : "!b0";
            case 3:
                return "e0 " + (random.nextBoolean() ? "=" : "!=") + " e0::" + "ABC".charAt(random.nextInt(3));
            case 4: // an event alone is no boolean condition; the pattern 'ev0 & b0' is not one either
                return "c1 > " + number(random.nextInt(9) - 4.5);
            case 5:
                return "c1 * p0 + 1 " + cmp() + " " + number(random.nextInt(5) - 1);
            case 6:
                return varpointTest();
            case 7:
                return condition(depth - 1) + " & " + condition(depth - 1);
            case 8:
                return condition(depth - 1) + " | " + condition(depth - 1);
            default:
                return "!(" + condition(depth - 1) + ")";
        }
    }

    /** A test on a varpoint's value, in a condition or as a consequence. */
    private String varpointTest() {
        int v = random.nextInt(kinds.size());
        char[] k = kinds.get(v);
        String name = "v" + v;
        switch (k[0]) {
            case 'e':
                return name + (random.nextInt(3) > 0 ? " = " : " != ") + name + "::x" + random.nextInt(sizes.get(v));
            case 'b':
                return name + " = " + random.nextBoolean();
            default:
                double x = onGrid(k[1]); // the validator refuses values off the precision grid
                int form = random.nextInt(6);
                if (form == 0) {
                    return name + " = " + number(x);
                } else if (form == 1) {
                    return name + " != " + number(x);
                } else if (form == 2) {
                    return name + " = c0 / 2";
                } else if (form == 3) {
                    int w = random.nextInt(kinds.size());
                    return w == v || kinds.get(w)[0] != 'n' ? name + " >= " + number(x)
                            : name + " + v" + w + " " + cmp() + " " + number(x);
                }
                return name + " " + cmp() + " " + number(x);
        }
    }

    private String consequence() {
        return random.nextInt(4) == 0 ? varpointTest() + " | " + varpointTest() : varpointTest();
    }

    private String cmp() {
        return COMPARISONS[random.nextInt(COMPARISONS.length)];
    }

    private static String number(double x) {
        return x == Math.rint(x) ? Long.toString((long) x)
                : java.math.BigDecimal.valueOf(x).stripTrailingZeros().toPlainString();
    }
}
