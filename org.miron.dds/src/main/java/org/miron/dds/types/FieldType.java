package org.miron.dds.types;

/**
 * The type of one field: a primitive (a string maybe bounded) or a nested message by its full name
 * ({@code std_msgs/Header}), alone or as an array: fixed ({@code [3]}), bounded ({@code [<=3]}) or
 * unbounded ({@code []}).
 *
 * @param primitive   the primitive, or null for a nested message
 * @param message     the nested message's full name {@code pkg/Name}, or null
 * @param stringBound the most characters of a bounded string ({@code string<=10}), or -1
 * @param array       how many values the field holds
 * @param size        the length of a fixed array, the bound of a bounded one, else -1
 */
public record FieldType(Primitive primitive, String message, int stringBound, Array array, int size) {
    /** One value, or an array of values of a kind. */
    public enum Array {
        NONE, FIXED, BOUNDED, UNBOUNDED
    }

    /** The same element type, as one value. */
    public FieldType element() {
        return new FieldType(primitive, message, stringBound, Array.NONE, -1);
    }

    public boolean isArray() {
        return array != Array.NONE;
    }

    /** The type as a .msg writes it ({@code string<=5[<=3]}), for messages. */
    @Override
    public String toString() {
        String base = primitive != null ? primitive.msgName() + (stringBound >= 0 ? "<=" + stringBound : "") : message;
        return switch (array) {
            case NONE -> base;
            case FIXED -> base + "[" + size + "]";
            case BOUNDED -> base + "[<=" + size + "]";
            case UNBOUNDED -> base + "[]";
        };
    }
}
