package org.miron.dds.types;

import java.util.Locale;

/**
 * The primitive field types of ROS 2 message definitions (rosidl's .msg names; the .idl spellings
 * map onto them in {@link IdlParser}), with their CDR size, which is also their XCDR1 alignment.
 */
public enum Primitive {
    BOOL(1), BYTE(1), CHAR(1), INT8(1), UINT8(1), INT16(2), UINT16(2), INT32(4), UINT32(4), INT64(8), UINT64(8),
    FLOAT32(4), FLOAT64(8), STRING(4), WSTRING(4);

    /** Bytes of one value on the wire (the length prefix for strings). */
    public final int size;

    Primitive(int size) {
        this.size = size;
    }

    /** The .msg spelling ({@code float32}, {@code string}). */
    public String msgName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The type by its .msg spelling, or null. */
    public static Primitive ofMsg(String name) {
        for (Primitive p : values()) {
            if (p.msgName().equals(name)) {
                return p;
            }
        }
        return null;
    }

    public boolean isString() {
        return this == STRING || this == WSTRING;
    }

    public boolean isInteger() {
        return this != BOOL && this != FLOAT32 && this != FLOAT64 && !isString();
    }

    public boolean isFloat() {
        return this == FLOAT32 || this == FLOAT64;
    }
}
