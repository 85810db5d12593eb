package org.miron.lsp.diagram;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.function.BiFunction;

import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SNode;
import org.junit.After;
import org.junit.Test;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * The diagram servers of a connection with the language server's reads replaced by futures the
 * test completes: which model a client gets when reads end out of order, are cancelled or race.
 */
public class DiagramServersTest {
    private final List<JsonObject> sent = new ArrayList<>();
    private static final int READERS = 4;
    private final ExecutorService readers = Executors.newFixedThreadPool(READERS);

    @After
    public void stop() {
        readers.shutdownNow();
    }

    private DiagramServers servers(BiFunction<String, Set<String>, CompletableFuture<DiagramGeneration.Generated>> generate) {
        DiagramServers servers = new DiagramServers(generate, uri -> uri);
        servers.connect((method, params) -> {
            if (method.equals("diagram/accept")) {
                synchronized (sent) {
                    sent.add(((JsonElement) params).getAsJsonObject());
                }
            }
        });
        return servers;
    }

    @Test
    public void aReadThatEndsAfterANewerRequestIsNotShown() {
        Map<String, CompletableFuture<DiagramGeneration.Generated>> reads = new ConcurrentHashMap<>();
        DiagramServers servers = servers((uri, expanded) -> reads.computeIfAbsent(uri, u -> new CompletableFuture<>()));
        servers.accept(requestModel("one", "file:///w/a.bt", "r1"));
        servers.accept(requestModel("one", "file:///w/b.miron", "r2"));
        reads.get("file:///w/b.miron").complete(model("file:///w/b.miron"));
        reads.get("file:///w/a.bt").complete(model("file:///w/a.bt"));
        List<JsonObject> models = models();
        assertEquals(1, models.size());
        assertEquals("setModel", kind(models.get(0)));
        assertEquals("r2", action(models.get(0)).get("responseId").getAsString());
        assertEquals("file:///w/b.miron", shownFile(models.get(0)));
    }

    @Test
    public void aReadCancelledByAWriteThatBuildsNothingIsMadeAgain() throws Exception {
        List<String> asked = new ArrayList<>();
        DiagramServers servers = servers((uri, expanded) -> {
            synchronized (asked) {
                asked.add(uri);
                if (asked.size() == 1) {
                    CompletableFuture<DiagramGeneration.Generated> cancelled = new CompletableFuture<>();
                    cancelled.cancel(true);
                    return cancelled;
                }
            }
            return CompletableFuture.completedFuture(model(uri));
        });
        servers.accept(requestModel("one", "file:///w/b.miron", "r1"));
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (models().isEmpty() && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertEquals(List.of("file:///w/b.miron", "file:///w/b.miron"), asked);
        assertEquals("r1", action(models().get(0)).get("responseId").getAsString());
    }

    // Reads end on several threads while the client asks for one file, then another: whatever the
    // interleaving, the last model the client gets is the file it asked for last, and each model
    // request gets one answer at most.
    @Test
    public void racingReadsNeverLeaveAnOlderFileShown() throws Exception {
        DiagramServers servers = servers((uri, expanded) -> CompletableFuture.supplyAsync(() -> {
            if (ThreadLocalRandom.current().nextBoolean()) {
                Thread.yield();
            }
            return model(uri);
        }, readers));
        String last = null;
        for (int i = 0; i < 300; i++) {
            last = i % 2 == 0 ? "file:///w/a.bt" : "file:///w/b.miron";
            servers.accept(requestModel("one", last, "r" + i));
            if (i % 3 == 0) {
                servers.refreshAll();
            }
            if (i % 10 == 9) {
                String expected = last;
                servers.refreshAllAndWait().get(10, TimeUnit.SECONDS);
                idle();
                List<JsonObject> models = models();
                assertEquals("after request r" + i, expected, shownFile(models.get(models.size() - 1)));
            }
        }
        Map<String, Integer> answers = new ConcurrentHashMap<>();
        for (JsonObject model : models()) {
            if (action(model).has("responseId")) {
                answers.merge(action(model).get("responseId").getAsString(), 1, Integer::sum);
            }
        }
        assertTrue(answers.toString(), answers.values().stream().allMatch(n -> n == 1));
    }

    /** Waits until every reader thread is free: the reads queued before have ended, and shown what they would. */
    private void idle() throws Exception {
        CyclicBarrier all = new CyclicBarrier(READERS);
        List<java.util.concurrent.Future<Integer>> waits = new ArrayList<>();
        for (int i = 0; i < READERS; i++) {
            waits.add(readers.submit(() -> all.await(10, TimeUnit.SECONDS)));
        }
        for (java.util.concurrent.Future<Integer> wait : waits) {
            wait.get(10, TimeUnit.SECONDS);
        }
    }

    private static JsonObject requestModel(String clientId, String uri, String requestId) {
        JsonObject options = new JsonObject();
        options.addProperty("sourceUri", uri);
        options.addProperty("diagramType", "miron-diagram");
        JsonObject action = new JsonObject();
        action.addProperty("kind", "requestModel");
        action.add("options", options);
        action.addProperty("requestId", requestId);
        JsonObject message = new JsonObject();
        message.addProperty("clientId", clientId);
        message.add("action", action);
        return message;
    }

    /** A one-node graph whose node is named after the file it was read from. */
    private static DiagramGeneration.Generated model(String uri) {
        SGraph graph = new SGraph();
        graph.setType("graph");
        graph.setId("graph");
        SNode node = new SNode();
        node.setType("node:action");
        node.setId(uri);
        graph.setChildren(new ArrayList<>(List.of(node)));
        return new DiagramGeneration.Generated(graph, Map.of(), true);
    }

    private List<JsonObject> models() {
        synchronized (sent) {
            return sent.stream().filter(m -> kind(m).equals("setModel") || kind(m).equals("updateModel")).toList();
        }
    }

    private static JsonObject action(JsonObject message) {
        return message.getAsJsonObject("action");
    }

    private static String kind(JsonObject message) {
        return action(message).get("kind").getAsString();
    }

    private static String shownFile(JsonObject model) {
        return action(model).getAsJsonObject("newRoot").getAsJsonArray("children").get(0).getAsJsonObject().get("id").getAsString();
    }
}
