package org.miron.runtime.live;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Set;
import java.util.stream.Collectors;
import org.miron.executor.ActionRegistry;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.TreeBuilder;
import org.miron.executor.TreeContext;
import org.miron.executor.skills.SkillActionStrategy;
import org.miron.executor.skills.VariantActionNode;
import org.miron.executor.skills.VariantSource;
import org.miron.executor.trace.StatusListener;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.groot.GrootServer;
import org.miron.runtime.recording.BtlogWriter;
import org.miron.runtime.skill.SkillDeadlines;
import org.miron.runtime.skill.ZmqSkillClient;

/**
 * A (woven) behaviour tree running against a live MIRoN installation: VariantAction nodes follow
 * the engine's {@code miron.variant.<vp>} decisions, numeric {@code miron.blackboard.<vp>}
 * decisions reach the blackboard, and every other action is a skill pushed to the SmartSoft skill
 * interface (Java actions registered on {@link #registry()} before {@link #build} take precedence).
 */
public final class LiveExecutor implements AutoCloseable {
    private final Endpoints endpoints;
    private final ActionRegistry registry = new ActionRegistry();
    private final VariantSource variants = new VariantSource();
    private final VariantSource blackboard = new VariantSource();
    private SkillDeadlines deadlines = SkillDeadlines.defaults();
    private ZmqSkillClient skills;
    private DecisionFeed feed;
    private Tree tree;
    private GrootServer groot;
    private BtlogWriter recording;
    private Path treeFile;

    public LiveExecutor(Endpoints endpoints) {
        this.endpoints = endpoints;
    }

    /** Actions to run in Java instead of as skills; register them before {@link #build}. */
    public ActionRegistry registry() {
        return registry;
    }

    /** Result deadlines of pushed skills (see {@link ZmqSkillClient}); set before {@link #build}. */
    public LiveExecutor skillDeadlines(SkillDeadlines deadlines) {
        this.deadlines = deadlines;
        return this;
    }

    /** Loads and checks the tree and connects to the bus and the skill interface. */
    public LiveExecutor build(Path treeFile, StatusListener trace) {
        skills = new ZmqSkillClient(endpoints.request(), endpoints.skillEvents(), 2000, deadlines);
        registry.registerVariantAction(variants).setFallback(new SkillActionStrategy(skills));
        this.treeFile = treeFile;
        tree = new TreeBuilder(registry, new TreeContext()).build(treeFile);
        if (trace != null) {
            tree.addListener(trace);
        }
        tree.feedBlackboardFrom(blackboard);
        skills.start();
        feed = new DecisionFeed(endpoints.busIn(), endpoints.busOut(), variants, blackboard).start();
        // Monitors follow the run on the bus: the tree, then every status change (docs/wire-formats.md).
        StatusPublisher statuses = new StatusPublisher(tree, feed::publish);
        feed.publishRetained(Topics.BT_TREE, statuses.treeMessage(treeFile.toAbsolutePath().toString()));
        tree.addListener(statuses);
        return this;
    }

    /**
     * Serves Groot2's protocol for the built tree on 127.0.0.1:port (and port + 1), as BT.CPP's
     * Groot2Publisher does (org.miron.runtime.groot); call it after {@link #build}, before running.
     */
    public LiveExecutor serveGroot(int port) {
        if (tree == null) {
            throw new IllegalStateException("build the tree before serving Groot2");
        }
        groot = GrootServer.start(tree, port, treeFile);
        return this;
    }

    /**
     * Records the run into {@code btlog} as BehaviorTree.CPP's FileLogger2 does
     * (org.miron.runtime.recording); call it after {@link #build}, before running.
     */
    public LiveExecutor record(Path btlog) throws java.io.IOException {
        if (tree == null) {
            throw new IllegalStateException("build the tree before recording it");
        }
        recording = BtlogWriter.start(tree, btlog, treeFile);
        return this;
    }

    /** The Groot2 server, or null without {@link #serveGroot}. */
    public GrootServer groot() {
        return groot;
    }

    /**
     * Ticks the tree every {@code period} until it finishes or {@link #stop()} is called. The first
     * tick waits (at most {@link #DECISION_WAIT}) for a decision on every varpoint the tree follows:
     * a running engine has one in the broker's cache, and the robot should not start the nominal
     * behaviour for the few milliseconds it takes to arrive. Without an engine it starts anyway.
     */
    public NodeStatus run(Duration period) {
        awaitDecisions(DECISION_WAIT);
        return tree.tickWhileRunning(period);
    }

    /** How long the first tick waits for the current decisions. */
    public static final Duration DECISION_WAIT = Duration.ofSeconds(2);

    /** Waits until every VariantAction's varpoint has a decision; false on timeout. */
    boolean awaitDecisions(Duration timeout) {
        Set<String> followed = tree.nodes().stream().filter(VariantActionNode.class::isInstance)
                .map(n -> ((VariantActionNode) n).varpoint()).collect(Collectors.toSet());
        long end = System.nanoTime() + timeout.toNanos();
        while (!variants.snapshot().keySet().containsAll(followed)) {
            if (System.nanoTime() > end) {
                return false;
            }
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return true;
    }

    /** Ends a {@link #run} from another thread (it halts the tree, aborting running skills). */
    public void stop() {
        if (groot != null) {
            groot.close(); // a tree paused at a breakpoint goes on, so it can see the stop
        }
        if (tree != null) {
            tree.stop();
        }
    }

    public Tree tree() {
        return tree;
    }

    /** The decisions received so far (enum varpoints), for reports and tests. */
    public VariantSource variants() {
        return variants;
    }

    @Override
    public void close() {
        stop();
        if (recording != null) {
            recording.close(); // after the stop: the halt's transitions to IDLE are recorded
        }
        if (feed != null) {
            feed.close();
        }
        if (skills != null) {
            skills.close();
        }
    }
}
