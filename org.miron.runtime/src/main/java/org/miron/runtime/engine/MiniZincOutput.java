package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.miron.runtime.Json;

/**
 * Reads MiniZinc's {@code --json-stream --output-mode json} output: one JSON object per line
 * ({@code solution}, {@code status}, {@code error}, {@code warning}, ...). Non-JSON lines are
 * ignored. Synchronized: a reader thread feeds it, the solve thread reads the result. With {@code solve maximize} several solutions arrive; the last one is the best.
 */
final class MiniZincOutput {
    private JsonNode lastSolution;
    private String status;
    private final List<String> errors = new ArrayList<>();

    synchronized void line(String line) {
        String s = line.trim();
        if (!s.startsWith("{")) {
            return;
        }
        JsonNode msg;
        try {
            msg = Json.MAPPER.readTree(s);
        } catch (IOException e) {
            return;
        }
        switch (msg.path("type").asText()) {
            case "solution":
                lastSolution = solutionObject(msg.path("output").get("json"));
                break;
            case "status":
                status = msg.path("status").asText();
                break;
            case "error":
                errors.add(describeError(msg));
                break;
            default:
                break; // warnings, statistics, comments
        }
    }

    /** The json section is an object in MiniZinc 2.6; older releases give it as a string. */
    private static JsonNode solutionObject(JsonNode json) {
        if (json != null && json.isTextual()) {
            try {
                return Json.MAPPER.readTree(json.asText());
            } catch (IOException e) {
                return null;
            }
        }
        return json;
    }

    private static String describeError(JsonNode msg) {
        StringBuilder b = new StringBuilder();
        if (msg.hasNonNull("what")) {
            b.append(msg.get("what").asText()).append(": ");
        }
        b.append(msg.path("message").asText(""));
        JsonNode loc = msg.get("location");
        if (loc != null) {
            b.append(" (").append(loc.path("filename").asText()).append(':').append(loc.path("firstLine").asInt())
                    .append(')');
        }
        return b.toString();
    }

    /**
     * @param exitCode process exit code
     * @param stderr   tail of the error stream, for crashes
     */
    synchronized SolveResult result(IoModel model, int exitCode, String stderr, long millis) {
        if (!errors.isEmpty()) {
            return SolveResult.failed(SolveResult.Status.ERROR, "minizinc error: " + String.join("; ", errors), millis);
        }
        if (status != null && (status.equals("UNSATISFIABLE") || status.startsWith("UNSAT") || status.equals("UNBOUNDED"))) {
            return SolveResult.failed(SolveResult.Status.UNSAT, "model is " + status.toLowerCase(), millis);
        }
        if (lastSolution == null && "UNKNOWN".equals(status)) {
            return SolveResult.failed(SolveResult.Status.TIMEOUT, "no solution within the time limit", millis);
        }
        if (exitCode != 0) {
            return SolveResult.failed(SolveResult.Status.ERROR,
                    "minizinc exited with code " + exitCode + (stderr.isBlank() ? "" : ": " + stderr.strip()), millis);
        }
        if (lastSolution == null || !lastSolution.isObject()) {
            return SolveResult.failed(SolveResult.Status.ERROR, "minizinc printed no solution (status "
                    + status + ")", millis);
        }
        Map<String, Integer> decisions = new LinkedHashMap<>();
        for (VariationPoint vp : model.varpoints()) {
            JsonNode v = lastSolution.get(vp.decision());
            if (v == null || !v.canConvertToInt() || !v.isIntegralNumber()) {
                return SolveResult.failed(SolveResult.Status.ERROR,
                        "solution has no integer " + vp.decision() + ": " + lastSolution, millis);
            }
            decisions.put(vp.decision(), v.asInt());
        }
        boolean optimal = status == null || status.equals("OPTIMAL_SOLUTION") || status.equals("ALL_SOLUTIONS");
        return new SolveResult(SolveResult.Status.SOLVED, decisions, optimal, "", millis);
    }
}
