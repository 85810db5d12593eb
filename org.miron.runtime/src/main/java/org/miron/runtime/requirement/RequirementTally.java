package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.miron.runtime.Json;
import org.miron.runtime.requirement.RequirementModel.Requirement;
import org.miron.runtime.requirement.RequirementModel.Signal;

/**
 * Each requirement's verdict so far on a live run, for {@code miron.requirement.status}: violated
 * once any violation was told, not-evaluated while a signal it reads has never had a value, else
 * holds; the exact verdicts (open windows decided) once the run is finished. Owned by one thread.
 */
final class RequirementTally {
    private final RequirementModel model;
    private final Map<String, Integer> violations = new LinkedHashMap<>();
    private final Map<String, Boolean> violatedNow = new LinkedHashMap<>();
    private final Set<String> valued = new HashSet<>();
    private final Map<String, Set<String>> reads = new LinkedHashMap<>();
    private List<RequirementResult> results;

    RequirementTally(RequirementModel model) {
        this.model = model;
        for (Signal s : model.signals()) {
            if (s.isEvent() || (s.isVarpoint() && s.initial() != null)) {
                valued.add(s.name()); // known from the start (see Signals)
            }
        }
        for (Requirement r : model.requirements()) {
            Set<String> signals = new HashSet<>(r.reads());
            collectReads(r.formula(), signals);
            reads.put(r.name(), signals);
            violations.put(r.name(), 0);
            violatedNow.put(r.name(), false);
        }
    }

    /** The signals a formula reads, by their params and varpoint names (a hand-written file may list no reads). */
    private void collectReads(JsonNode f, Set<String> out) {
        for (Signal s : model.signals()) {
            String key = s.isVarpoint() ? s.source() : s.param();
            if (s.isVarpoint() ? key.equals(f.path("index").asText(null)) || key.equals(f.path("value").asText(null))
                    : key.equals(f.path("param").asText(null))) {
                out.add(s.name());
            }
        }
        f.forEach(child -> collectReads(child, out));
    }

    /** A value of the signals fed from this source (a context, property or varpoint name) was taken. */
    void valued(String kind, String source) {
        for (Signal s : model.signals()) {
            if (s.kind().equals(kind) && s.source().equals(source)) {
                valued.add(s.name());
            }
        }
    }

    void told(RequirementEvent e) {
        boolean violated = e.verdict().equals(RequirementEvent.VIOLATED);
        violatedNow.put(e.name(), violated);
        if (violated) {
            violations.merge(e.name(), 1, Integer::sum);
        }
    }

    void finished(List<RequirementResult> finalResults) {
        this.results = finalResults;
    }

    String verdict(Requirement r) {
        if (results != null) {
            for (RequirementResult x : results) {
                if (x.name().equals(r.name())) {
                    return x.verdict().id();
                }
            }
        }
        if (violations.get(r.name()) > 0) {
            return Verdict.VIOLATED.id();
        }
        return valued.containsAll(reads.get(r.name())) ? Verdict.HOLDS.id() : Verdict.NOT_EVALUATED.id();
    }

    /** {@code {name: {"verdict", "violations", "violatedNow"}}} in declaration order. */
    ObjectNode json() {
        ObjectNode o = Json.object();
        for (Requirement r : model.requirements()) {
            int n = violations.get(r.name());
            if (results != null) {
                n = results.stream().filter(x -> x.name().equals(r.name())).mapToInt(RequirementResult::violations)
                        .findFirst().orElse(n);
            }
            o.putObject(r.name()).put("verdict", verdict(r)).put("violations", n)
                    .put("violatedNow", violatedNow.get(r.name()));
        }
        return o;
    }
}
