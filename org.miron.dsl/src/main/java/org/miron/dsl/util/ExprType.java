package org.miron.dsl.util;

import org.miron.dsl.roqme.EnumType;

/** The static type of an expression: a kind, plus the enumeration for enum values. */
public final class ExprType {

    public enum Kind { BOOLEAN, NUMBER, TIME, EVENT, ENUM, STRING, UNKNOWN }

    public static final ExprType BOOLEAN = new ExprType(Kind.BOOLEAN, null);
    public static final ExprType NUMBER = new ExprType(Kind.NUMBER, null);
    public static final ExprType TIME = new ExprType(Kind.TIME, null);
    public static final ExprType EVENT = new ExprType(Kind.EVENT, null);
    public static final ExprType STRING = new ExprType(Kind.STRING, null);
    /** Unresolved references and the like: already reported elsewhere, never reported again. */
    public static final ExprType UNKNOWN = new ExprType(Kind.UNKNOWN, null);

    public final Kind kind;
    public final EnumType enumType;

    private ExprType(Kind kind, EnumType enumType) {
        this.kind = kind;
        this.enumType = enumType;
    }

    public static ExprType enumOf(EnumType type) {
        return type == null ? UNKNOWN : new ExprType(Kind.ENUM, type);
    }

    public boolean isUnknown() {
        return kind == Kind.UNKNOWN;
    }

    /** Numbers and times mix freely (a time context compared with 5 seconds, a time divided by 2). */
    public boolean isNumeric() {
        return kind == Kind.NUMBER || kind == Kind.TIME || isUnknown();
    }

    /** Conditions and patterns: booleans, and events in event patterns. */
    public boolean isLogical() {
        return kind == Kind.BOOLEAN || kind == Kind.EVENT || isUnknown();
    }

    /**
     * Operands of the event operators (or, and, not, ->, once...) and observation patterns: also
     * enum contexts and literals, whose change of value is the event (as real RoQME models write
     * "ctx := Mode::BUMP" for "when the context becomes BUMP").
     */
    public boolean isEventLike() {
        return isLogical() || kind == Kind.ENUM;
    }

    /** Whether values of both types can be compared with = and !=. */
    public boolean comparableWith(ExprType other) {
        if (isUnknown() || other.isUnknown()) {
            return true;
        }
        if (isNumeric() && other.isNumeric()) {
            return true;
        }
        if (kind == Kind.ENUM && other.kind == Kind.ENUM) {
            return enumType == other.enumType;
        }
        return kind == other.kind;
    }

    @Override
    public String toString() {
        switch (kind) {
        case ENUM:
            return "enum " + Names.enumName(enumType);
        case UNKNOWN:
            return "unknown";
        default:
            return kind.name().toLowerCase();
        }
    }
}
