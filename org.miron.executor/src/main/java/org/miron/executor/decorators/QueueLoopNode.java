package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.IF_EMPTY;
import static org.miron.bt.nodes.BuiltinNodes.QUEUE;
import static org.miron.bt.nodes.BuiltinNodes.VALUE;

import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Deque;
import java.util.function.Function;
import org.miron.executor.BtRuntimeException;
import org.miron.executor.Conversions;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.Ports;

/**
 * LoopInt, LoopDouble, LoopString, LoopBool(queue, if_empty = SUCCESS, value) (BT.CPP 4's
 * LoopNode): while the queue has elements, pops the first into {@code value} and ticks the child,
 * returning RUNNING after each SUCCESS of the child so the next tick takes the next element; a
 * FAILURE of the child ends the node with FAILURE; an empty queue (when the child is not running)
 * returns if_empty. A literal queue ("1;2;3") starts over full on each run; a queue in the
 * blackboard is consumed in place. Unlike BT.CPP, a blackboard entry holding text is read as a
 * literal queue (and replaced by what is left of it).
 */
public final class QueueLoopNode extends DecoratorNode {
    private final Function<String, Object> element;
    private Deque<Object> queue;
    private boolean childRunning;

    public QueueLoopNode(NodeInfo info, Node child, Function<String, Object> element) {
        super(info, child);
        this.element = element;
    }

    /** The element type of a Loop tag (LoopInt ...), or null when the tag is not a queue loop. */
    public static Function<String, Object> elementType(String tag) {
        switch (tag) {
            case "LoopInt":
                return text -> (long) Conversions.toInt(text);
            case "LoopDouble":
                return Conversions::toDouble;
            case "LoopBool":
                return text -> Conversions.toBoolean(text) ? 1L : 0L;
            case "LoopString":
                return text -> text;
            default:
                return null;
        }
    }

    @Override
    protected NodeStatus tick() {
        String raw = ports().raw(QUEUE);
        boolean literal = raw == null || Ports.blackboardKey(QUEUE, raw).isEmpty();
        if (status() == NodeStatus.IDLE) {
            childRunning = false;
            if (literal) {
                queue = parse(raw == null ? "" : raw);
            }
        }
        boolean popped = false;
        if (!childRunning) {
            if (!literal) {
                queue = fromBlackboard(raw);
            }
            if (queue != null && !queue.isEmpty()) {
                ports().set(VALUE, queue.pollFirst());
                popped = true;
            }
        }
        if (!popped && !childRunning) {
            return ports().get(IF_EMPTY).map(Conversions::toStatusOrSkipped).orElse(NodeStatus.SUCCESS);
        }
        if (status() == NodeStatus.IDLE) {
            setStatus(NodeStatus.RUNNING);
        }
        NodeStatus childStatus = child.executeTick();
        childRunning = childStatus == NodeStatus.RUNNING;
        if (childStatus.isCompleted()) {
            resetChild();
        }
        return childStatus == NodeStatus.FAILURE ? NodeStatus.FAILURE : NodeStatus.RUNNING;
    }

    @SuppressWarnings("unchecked")
    private Deque<Object> fromBlackboard(String raw) {
        String key = Ports.blackboardKey(QUEUE, raw).orElseThrow();
        Object value = ports().blackboard().get(key).orElse(null);
        if (value == null) {
            return null;
        }
        if (value instanceof Deque<?> deque) {
            return (Deque<Object>) deque;
        }
        Deque<Object> parsed = value instanceof Collection<?> items ? new ArrayDeque<>(items) : parse(String.valueOf(value));
        ports().blackboard().set(key, parsed);
        return parsed;
    }

    private Deque<Object> parse(String text) {
        Deque<Object> items = new ArrayDeque<>();
        if (text.isEmpty()) {
            return items;
        }
        for (String part : text.split(";", -1)) {
            try {
                items.add(element.apply(part.trim()));
            } catch (IllegalArgumentException e) {
                throw new BtRuntimeException(path() + ": queue: " + e.getMessage(), e);
            }
        }
        return items;
    }
}
