package org.miron.executor;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.miron.executor.skills.SkillClient;
import org.miron.executor.skills.SkillHandle;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;

/** Records push-skill requests; the test completes them. An abort completes the skill with ABORT. */
final class FakeSkillClient implements SkillClient {
    final List<SkillRequest> requests = new ArrayList<>();
    final List<CompletableFuture<SkillResult>> results = new ArrayList<>();
    int aborts;

    @Override
    public SkillHandle pushSkill(SkillRequest request) {
        requests.add(request);
        CompletableFuture<SkillResult> result = new CompletableFuture<>();
        results.add(result);
        return SkillHandle.of(result, () -> {
            aborts++;
            result.complete(SkillResult.of(SkillResult.Outcome.ABORT));
        });
    }

    SkillRequest last() {
        return requests.get(requests.size() - 1);
    }

    void completeLast(SkillResult.Outcome outcome) {
        results.get(results.size() - 1).complete(SkillResult.of(outcome));
    }
}
