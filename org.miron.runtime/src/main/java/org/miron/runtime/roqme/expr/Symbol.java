package org.miron.runtime.roqme.expr;

import org.miron.runtime.roqme.model.RoqmeModel.Type;

/** A declaration's slot in the {@link Store} and what it is. */
public record Symbol(String id, Kind kind, int slot, Type type, String at) {
    public enum Kind { CONTEXT, PARAM, VAR, TIMER, BELIEF }

    /** Contexts of kind eventtype and timers are events by themselves. */
    public boolean isEvent() {
        return kind == Kind.TIMER || (type != null && "eventtype".equals(type.kind()));
    }

    public String valueType() {
        if (isEvent()) {
            return "event";
        }
        if (kind == Kind.BELIEF) {
            return "number";
        }
        return type == null ? "unknown" : type.kind();
    }
}
