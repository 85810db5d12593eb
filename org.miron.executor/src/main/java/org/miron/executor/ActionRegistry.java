package org.miron.executor;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import java.util.function.Supplier;
import org.miron.executor.skills.VariantActionNode;
import org.miron.executor.skills.VariantSource;

/**
 * Resolves Action and Condition IDs to runtime nodes: Java actions registered here first, then the
 * fallback strategy for every other ID. User-registered control nodes and decorators (elements with
 * children) are resolved here too, by ID, without fallback.
 */
public final class ActionRegistry {
    /** The ID the weaver gives the node that follows a variation point's decisions. */
    public static final String VARIANT_ACTION = "VariantAction";

    private final Map<String, ActionFactory> factories = new ConcurrentHashMap<>();
    private final Map<String, ControlFactory> controls = new ConcurrentHashMap<>();
    private final Map<String, DecoratorFactory> decorators = new ConcurrentHashMap<>();
    private final Map<String, Integer> scriptingEnums = new ConcurrentHashMap<>();
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

    /** A custom control node: {@code <Control ID="id">} or {@code <id>children</id>}; one node per element. */
    public ActionRegistry registerControl(String id, ControlFactory factory) {
        controls.put(Objects.requireNonNull(id), Objects.requireNonNull(factory));
        return this;
    }

    /** A custom decorator: {@code <Decorator ID="id">} or {@code <id>child</id>}; one node per element. */
    public ActionRegistry registerDecorator(String id, DecoratorFactory factory) {
        decorators.put(Objects.requireNonNull(id), Objects.requireNonNull(factory));
        return this;
    }

    public boolean isControlRegistered(String id) {
        return controls.containsKey(id);
    }

    public boolean isDecoratorRegistered(String id) {
        return decorators.containsKey(id);
    }

    /** The node of a custom control element, built from its children. */
    public Node createControl(String id, NodeInfo info, List<Node> children) {
        ControlFactory factory = controls.get(id);
        if (factory == null) {
            throw new BtBuildException(info.path() + ": no control node is registered for ID '" + id
                    + "' (register it with ActionRegistry.registerControl)");
        }
        return made(factory.create(info, children), id, info);
    }

    /** The node of a custom decorator element, built from its child. */
    public Node createDecorator(String id, NodeInfo info, Node child) {
        DecoratorFactory factory = decorators.get(id);
        if (factory == null) {
            throw new BtBuildException(info.path() + ": no decorator is registered for ID '" + id
                    + "' (register it with ActionRegistry.registerDecorator)");
        }
        return made(factory.create(info, child), id, info);
    }

    private static Node made(Node node, String id, NodeInfo info) {
        if (node == null) {
            throw new BtBuildException(info.path() + ": the factory for '" + id + "' made no node");
        }
        return node;
    }

    /**
     * A name version-4 scripts read as a number (BT.CPP 4's registerScriptingEnum): in
     * {@code _skipIf="color == RED"}, RED is this value. Enum names win over blackboard keys.
     */
    public ActionRegistry registerScriptingEnum(String name, int value) {
        scriptingEnums.put(Objects.requireNonNull(name), value);
        return this;
    }

    /** Every constant of a Java enum, by name, as its ordinal (BT.CPP 4's registerScriptingEnums). */
    public ActionRegistry registerScriptingEnums(Class<? extends Enum<?>> type) {
        for (Enum<?> constant : type.getEnumConstants()) {
            registerScriptingEnum(constant.name(), constant.ordinal());
        }
        return this;
    }

    /** The registered scripting enums, name to value (a snapshot). */
    public Map<String, Integer> scriptingEnums() {
        return Map.copyOf(scriptingEnums);
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
        return made(factory != null ? factory.create(spec) : fallback.create(spec), spec.id(), spec.info());
    }
}
