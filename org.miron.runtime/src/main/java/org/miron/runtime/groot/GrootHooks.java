package org.miron.runtime.groot;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.IntConsumer;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;
import org.miron.executor.trace.TickHook;

/**
 * Groot2's hooks on the nodes, and the tick hook that applies them, as BT.CPP's Groot2Publisher
 * does, oddities included: one hook a node, kept under PRE whatever position it was inserted with
 * (so a POST hook is listed as POST yet runs before the tick, and is found again only as PRE);
 * every hook reached publishes BREAKPOINT_REACHED, a REPLACE hook too. A breakpoint blocks only the
 * tick thread, until unlocked, removed or disabled (the heartbeat disables every hook when Groot2
 * goes quiet).
 */
final class GrootHooks implements TickHook {
    private final GrootTree tree;
    /** Told the uid of each hook reached (the server publishes the notice). */
    private final IntConsumer reached;
    private final Map<Integer, GrootHook> hooks = new ConcurrentHashMap<>();

    GrootHooks(GrootTree tree, IntConsumer reached) {
        this.tree = tree;
        this.reached = reached;
    }

    @Override
    public NodeStatus beforeTick(Node node) {
        GrootHook hook = hooks.get(tree.uid(node));
        if (hook == null) {
            return null;
        }
        synchronized (hook) {
            if (!hook.enabled) {
                return null;
            }
            reached.accept(hook.uid);
            if (hook.mode == GrootHook.BREAKPOINT) {
                while (!hook.ready && hook.enabled) {
                    try {
                        hook.wait();
                    } catch (InterruptedException e) {
                        // the tree is being stopped: go on with the tick, keep the flag for the tick loop
                        Thread.currentThread().interrupt();
                        return null;
                    }
                }
                hook.ready = false;
                if (!hook.enabled) {
                    return null;
                }
            }
            if (hook.once) {
                hooks.remove(hook.uid, hook);
            }
            return hook.desiredStatus;
        }
    }

    /** The hook at this position, as the library's getHook: POST hooks are never stored, so never found. */
    private GrootHook find(int position, int uid) {
        return position == GrootHook.PRE ? hooks.get(uid) : null;
    }

    /**
     * HOOK_INSERT of one hook: updates the hook found at its position (a breakpoint turned into a
     * replacement lets its waiting tick go), else adds a new one, silently not for an unknown uid.
     */
    void insert(GrootHook.HookJson json) {
        GrootHook existing = find(json.position(), json.uid());
        if (existing != null) {
            synchronized (existing) {
                boolean wasBreakpoint = existing.mode == GrootHook.BREAKPOINT;
                existing.update(json);
                if (wasBreakpoint && existing.mode == GrootHook.REPLACE) {
                    existing.ready = true;
                    existing.notifyAll();
                }
            }
            return;
        }
        if (tree.node(json.uid()) == null) {
            return; // the library ignores it and still replies as if it had been inserted
        }
        GrootHook hook = new GrootHook(json.uid());
        hook.update(json);
        GrootHook replaced = hooks.put(json.uid(), hook);
        if (replaced != null) {
            // a POST insert replaces the node's PRE hook; a tick waiting on that one would wait for
            // ever in the library (nothing can reach it any more): here it goes on
            synchronized (replaced) {
                replaced.enabled = false;
                replaced.notifyAll();
            }
        }
    }

    /** BREAKPOINT_UNLOCK: false (the library's "Node ID not found") when there is no such node or hook. */
    boolean unlock(int position, int uid, NodeStatus result, boolean remove) {
        GrootHook hook = tree.node(uid) == null ? null : find(position, uid);
        if (hook == null) {
            return false;
        }
        synchronized (hook) {
            hook.desiredStatus = result;
            hook.once |= remove;
            if (hook.mode == GrootHook.BREAKPOINT) {
                hook.ready = true;
                hook.notifyAll();
            }
        }
        return true;
    }

    /** HOOK_REMOVE: false when there is no such node or hook; a waiting breakpoint lets its tick go. */
    boolean remove(int position, int uid) {
        GrootHook hook = tree.node(uid) == null ? null : find(position, uid);
        if (hook == null) {
            return false;
        }
        hooks.remove(uid);
        synchronized (hook) {
            if (hook.mode == GrootHook.BREAKPOINT) {
                hook.enabled = false;
                hook.notifyAll();
            }
        }
        return true;
    }

    void removeAll() {
        for (Integer uid : List.copyOf(hooks.keySet())) {
            remove(GrootHook.PRE, uid);
        }
    }

    /** Enables or disables every hook (DISABLE_ALL_HOOKS, the heartbeat); disabling frees waiting breakpoints. */
    void enableAll(boolean enable) {
        for (GrootHook hook : hooks.values()) {
            synchronized (hook) {
                hook.enabled = enable;
                if (!enable && hook.mode == GrootHook.BREAKPOINT) {
                    hook.notifyAll();
                }
            }
        }
    }

    /** HOOKS_DUMP: every hook as JSON, in uid order (the library's is its hash map's). */
    JsonNode dump() {
        ArrayNode all = JsonNodeFactory.instance.arrayNode();
        hooks.keySet().stream().sorted().map(hooks::get).filter(h -> h != null).forEach(h -> all.add(h.toJson()));
        return all;
    }
}
