package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.dsl.miron.Implication;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.util.Formulas;
import org.miron.dsl.validation.MironIssueCodes;

/**
 * Requirements (docs/requirements.md): the documented shapes parse into the documented structure
 * (precedence, grouping), and each error carries its code at the place it is about.
 */
public class RequirementsTest {
    private static final File MODELS = new File("src/test/resources/models/miron");

    @Test
    public void formulasParseWithTheDocumentedPrecedence() {
        Map<String, Requirement> reqs = requirements(new File(MODELS, "valid/requirements.miron"));
        assertEquals("(always (implies (< r.autonomy 0.3) (eventually[5 seconds] (= style style::careful))))",
                tree(reqs.get("docksOnLowBattery").getFormula()));
        assertEquals("(never (and (< r.battery 1) (not r.docked)))", tree(reqs.get("neverStranded").getFormula()));
        assertEquals("(always (implies (< r.distance 1.5) (<= speed 0.3)))", tree(reqs.get("slowNearPeople").getFormula()));
        assertEquals(0.9, reqs.get("rarelyStranded").getProbability(), 0);
        assertEquals(null, reqs.get("neverStranded").getProbability());
        // always a and b is (always a) and b; temporal operators nest
        assertEquals("(and (always[10 minutes] (eventually[2 hours] r.docked)) (> r.safety 0.5))",
                tree(reqs.get("nested").getFormula()));
        // & and | bind tighter than the temporal operators, and implies groups to the right
        assertEquals("(never (| (& (< r.battery 5) (! r.docked)) (= r.space r::Level::LOW)))",
                tree(reqs.get("symbols").getFormula()));
        assertEquals("(implies r.docked (implies (> r.battery 10) (eventually[250 milliseconds] (>= speed 0.5))))",
                tree(reqs.get("chained").getFormula()));
        assertTrue(reqs.containsKey("requirement") && reqs.containsKey("within"));
        assertTrue(reqs.get("nested").getDocumentation().contains("Nesting, bounds in every unit"));
    }

    @Test
    public void errorsCarryTheirCodeWhereTheyAre() throws Exception {
        File file = new File(MODELS, "invalid/requirements.miron");
        List<Issue> issues = Models.validateAll(Models.load(file));
        List<String> lines = Files.readAllLines(file.toPath(), StandardCharsets.UTF_8);
        expect(issues, lines, 7, "r.battery", MironIssueCodes.REQUIREMENT_TYPE);
        expect(issues, lines, 8, "0 seconds", MironIssueCodes.REQUIREMENT_BOUND);
        expect(issues, lines, 9, "1 //!", MironIssueCodes.REQUIREMENT_PROBABILITY);
        expect(issues, lines, 10, "r.nothing", MironIssueCodes.REQUIREMENT_UNKNOWN_NAME);
        expect(issues, lines, 11, "r.battery'avg", MironIssueCodes.REQUIREMENT_PATTERN);
        expect(issues, lines, 12, "once", MironIssueCodes.REQUIREMENT_PATTERN);
        expect(issues, lines, 13, "belief", MironIssueCodes.REQUIREMENT_PATTERN);
        expect(issues, lines, 14, "r.battery > 5)", MironIssueCodes.REQUIREMENT_TEMPORAL_OUTSIDE);
        expect(issues, lines, 15, "always", MironIssueCodes.REQUIREMENT_TEMPORAL_OUTSIDE);
        expect(issues, lines, 16, "eventually", MironIssueCodes.REQUIREMENT_TEMPORAL_OUTSIDE);
        expect(issues, lines, 17, "a :", "roqme.duplicate-name");
        expect(issues, lines, 18, "(always", MironIssueCodes.REQUIREMENT_TYPE);
        // a negative bound is a bound, not the variable 'within' minus a time
        expect(issues, lines, 20, "-3 seconds", MironIssueCodes.REQUIREMENT_BOUND);
        // operand type errors inside a requirement are the requirement's; a comparison over a
        // temporal formula is told once
        expect(issues, lines, 21, "r.docked)", MironIssueCodes.REQUIREMENT_TYPE);
        expect(issues, lines, 22, "(eventually", MironIssueCodes.REQUIREMENT_TYPE);
        assertTrue(issues.stream().noneMatch(i -> "roqme.operand-type".equals(i.getCode())));
    }

    /** An issue with this code on this line, at the column where text starts. */
    private static void expect(List<Issue> issues, List<String> lines, int line, String text, String code) {
        int column = lines.get(line - 1).indexOf(text) + 1;
        assertTrue(text + " is on line " + line, column > 0);
        List<Issue> found = issues.stream().filter(i -> code.equals(i.getCode()) && i.getLineNumber() == line)
                .collect(Collectors.toList());
        assertEquals("issues " + code + " on line " + line + ": " + issues.stream().map(i -> i.getCode() + "@"
                + i.getLineNumber() + ":" + i.getColumn()).collect(Collectors.joining(", ")), 1, found.size());
        assertEquals(code + " on line " + line, column, (int) found.get(0).getColumn());
    }

    private static Map<String, Requirement> requirements(File file) {
        Resource resource = Models.load(file);
        assertTrue(resource.getErrors().toString(), resource.getErrors().isEmpty());
        Map<String, Requirement> byName = new LinkedHashMap<>();
        ((MironModel) resource.getContents().get(0)).getSentences().stream().filter(Requirement.class::isInstance)
                .map(Requirement.class::cast).forEach(r -> byName.put(r.getName(), r));
        return byName;
    }

    /** The formula as an s-expression: operators with their operands, names and literals as written. */
    private static String tree(Expression e) {
        if (e instanceof TemporalExpression t) {
            return "(" + t.getOperator().getLiteral() + (t.getBound() == null ? "" : "[" + Formulas.text(t.getBound()) + "]")
                    + " " + tree(t.getTerm()) + ")";
        } else if (e instanceof Implication i) {
            return "(implies " + tree(i.getLeft()) + " " + tree(i.getRight()) + ")";
        } else if (e instanceof BinaryExpression b) {
            return "(" + b.getOperator().getLiteral() + " " + tree(b.getLeft()) + " " + tree(b.getRight()) + ")";
        } else if (e instanceof UnaryExpression u) {
            return "(" + u.getOperator().getLiteral() + " " + tree(u.getTerm()) + ")";
        }
        return Formulas.text(e);
    }
}
