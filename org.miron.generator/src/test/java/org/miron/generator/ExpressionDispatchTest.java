package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.Test;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.RoqmeFactory;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.UnaryOperator;

/**
 * Both expression translators dispatch on EMF's generated switch: an expression class they have no
 * case for (here RoQME's string literal and range expression, which rules cannot use) is reported
 * at the element, never translated silently. ExpressionToTree does not repeat an error
 * ExpressionToMiniZinc, which runs first, has already reported.
 */
public class ExpressionDispatchTest {
    private static final RoqmeFactory ROQME = RoqmeFactory.eINSTANCE;

    @Test
    public void anExpressionClassWithoutCaseIsReportedByTheMiniZincTranslator() {
        List<GenerationError> errors = new ArrayList<>();
        Expression string = ROQME.createStringValue();
        String mzn = new ExpressionToMiniZinc(Map.of(), errors).translate(string, new ExpressionToMiniZinc.Mentions());
        assertEquals("false", mzn);
        assertEquals(1, errors.size());
        assertEquals(string, errors.get(0).source());
        assertTrue(errors.get(0).message(), errors.get(0).message().startsWith("cannot generate MiniZinc for ''"));
    }

    @Test
    public void anExpressionClassWithoutCaseIsReportedByTheTreeTranslator() {
        List<GenerationError> errors = new ArrayList<>();
        Expression range = ROQME.createRangeExpression();
        JsonNode tree = new ExpressionToTree(Map.of(), errors).translate(range);
        assertEquals("{\"const\":false}", tree.toString());
        assertEquals(1, errors.size());
        assertEquals(range, errors.get(0).source());
        assertTrue(errors.get(0).message(), errors.get(0).message().contains("RangeExpression has no case in ExpressionToTree"));
    }

    @Test
    public void theTreeTranslatorDoesNotRepeatWhatTheMiniZincTranslatorReported() {
        List<GenerationError> errors = new ArrayList<>();
        UnaryExpression once = ROQME.createUnaryExpression();
        once.setOperator(UnaryOperator.ONCE);
        once.setTerm(ROQME.createEventValue());
        new ExpressionToMiniZinc(Map.of(), errors).translate(once, new ExpressionToMiniZinc.Mentions());
        assertEquals(1, errors.size());
        assertTrue(errors.get(0).message(), errors.get(0).message().contains("'once'"));
        assertEquals("{\"const\":false}", new ExpressionToTree(Map.of(), errors).translate(once).toString());
        assertEquals(1, errors.size());
    }
}
