package org.miron.runtime.executor;

import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CompletableFuture;
import java.util.function.Function;
import java.util.function.Supplier;

/**
 * Resolves Action and Condition IDs to runtime nodes: Java actions registered here first, then the
 * fallback strategy for every other ID.
 */
public final class ActionRegistry {
    /** The ID the weaver gives the node that follows a variation point's decisions. */
    public static final String VARIANT_ACTION = "VariantAction";

    private final Map<String, ActionFactory> factories = new ConcurrentHashMap<>();
    private volatile UnregisteredActionStrategy fallback = UnregisteredActionStrategy.REJECT;

    /** Registers any node factory under an ID, replacing an earlier one. */
    public ActionRegistry register(String id, ActionFactory factory) {
        factories.put(Objects.requireNonNull(id), Objects.requireNonNull(factory));
        return this;
    }

    /** A Java action that finishes within a tick; the same instance serves every node with this ID. */
    public ActionRegistry registerSync(String id, SyncAction action) {
        Objects.requireNonNull(action);
        return register(id, spec -> new SyncActionNode(spec.info(), action));
    }

    /** A condition: like a synchronous action, it must not return RUNNING. */
    public ActionRegistry registerCondition(String id, SyncAction condition) {
        return registerSync(id, condition);
    }

    /** A Java action that may run over several ticks; one new instance per node. */
    public ActionRegistry registerAsync(String id, Supplier<? extends AsyncAction> actions) {
        Objects.requireNonNull(actions);
        return register(id, spec -> new AsyncActionNode(spec.info(), actions.get()));
    }

    /** A Java action running as a future started on its first tick and cancelled when halted. */
    public ActionRegistry registerFuture(String id, Function<Ports, CompletableFuture<NodeStatus>> start) {
        Objects.requireNonNull(start);
        return registerAsync(id, () -> new FutureAction(start));
    }

    /** Registers {@value #VARIANT_ACTION}, reading decisions from {@code variants}. */
    public ActionRegistry registerVariantAction(VariantSource variants) {
        Objects.requireNonNull(variants);
        return register(VARIANT_ACTION, spec -> new VariantActionNode(spec.info(), variants));
    }

    public ActionRegistry setFallback(UnregisteredActionStrategy strategy) {
        this.fallback = Objects.requireNonNull(strategy);
        return this;
    }

    public boolean isRegistered(String id) {
        return factories.containsKey(id);
    }

    public Set<String> registeredIds() {
        return new TreeSet<>(factories.keySet());
    }

    /** The node for one Action/Condition element of the tree. */
    public Node create(ActionSpec spec) {
        ActionFactory factory = factories.get(spec.id());
        Node node = factory != null ? factory.create(spec) : fallback.create(spec);
        if (node == null) {
            throw new BtBuildException(spec.info().path() + ": the factory for '" + spec.id() + "' made no node");
        }
        return node;
    }
}
