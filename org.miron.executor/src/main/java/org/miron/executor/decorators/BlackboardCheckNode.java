package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.RETURN_ON_MISMATCH;
import static org.miron.bt.nodes.BuiltinNodes.VALUE_A;
import static org.miron.bt.nodes.BuiltinNodes.VALUE_B;

import java.util.Objects;
import java.util.Optional;
import org.miron.executor.Conversions;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * BlackboardCheckInt/Double/String(value_A, value_B, return_on_mismatch=FAILURE): when both values
 * can be read as the type and are equal, ticks the child and returns its status; otherwise halts a
 * running child and returns return_on_mismatch.
 */
public class BlackboardCheckNode extends DecoratorNode {
    /** How the two values are read and compared. */
    public enum Kind {
        INT, DOUBLE, STRING
    }

    private final Kind kind;

    public BlackboardCheckNode(NodeInfo info, Kind kind, Node child) {
        super(info, child);
        this.kind = kind;
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        Optional<Object> a = read(VALUE_A);
        Optional<Object> b = read(VALUE_B);
        if (a.isPresent() && b.isPresent() && Objects.equals(a.get(), b.get())) {
            return child.executeTick();
        }
        resetChild();
        // Empty (as Groot writes unset ports) falls back to FAILURE, as in BehaviorTree.CPP 3.
        return ports().get(RETURN_ON_MISMATCH).filter(v -> !String.valueOf(v).isBlank())
                .map(Conversions::toStatus).orElse(NodeStatus.FAILURE);
    }

    /** The value as the check's type, or empty when missing or not convertible (a mismatch). */
    private Optional<Object> read(String port) {
        Optional<Object> value = ports().get(port);
        if (value.isEmpty()) {
            return value;
        }
        try {
            switch (kind) {
                case INT:
                    return Optional.of(Conversions.toInt(value.get()));
                case DOUBLE:
                    return Optional.of(Conversions.toDouble(value.get()));
                default:
                    return Optional.of(Conversions.toStringValue(value.get()));
            }
        } catch (IllegalArgumentException | ArithmeticException notConvertible) {
            return Optional.empty();
        }
    }
}
