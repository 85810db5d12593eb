package org.miron.dds.transport;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.nio.charset.StandardCharsets;
import us.ihmc.pubsub.participant.Participant;

/**
 * Makes a type registered with IHMC's library keyed in Fast-DDS. Why this exists: RoQME's original
 * types are keyed ({@code @key name}), and DDS never matches a keyed topic with an unkeyed one.
 * ihmc-pub-sub 0.20.0 registers every type natively as a {@code RawTopicDataType} whose constructor
 * (unlike 0.19's) takes no "has key" argument and leaves Fast-DDS's {@code m_isGetKeyDefined} false;
 * Fast-DDS then refuses a WITH_KEY writer or reader ("Keyed Topic needs getKey function"). The
 * native type itself already supports keys: its {@code getKey} copies the 16-byte key the Java side
 * hands to every write ({@code TopicDataType.getKey}) once that flag is set. So this sets the flag,
 * in the native object, right after registration.
 *
 * <p>It writes one byte of native memory, so it first checks the object it found is the one meant:
 * the layout is that of the pinned binaries (Fast-DDS 2.14's {@code TopicDataType} under the
 * Itanium C++ ABI: the type size at +8, the flag at +12, the name as a {@code std::string} at +0x40;
 * {@code NativeParticipantImpl}'s vector of registered types at +0x28). Any mismatch (another library
 * version, another ABI) ends in a {@link DdsException} naming it, before anything is written. See
 * docs/dds.md, "Keyed RoQME topics".
 */
final class NativeKeySwitch {
    private static final long TYPES_BEGIN = 0x28;
    private static final long TYPES_END = 0x30;
    private static final long TYPE_SIZE = 8;
    private static final long GET_KEY_DEFINED = 12;
    private static final long NAME_DATA = 0x40;
    private static final long NAME_LENGTH = 0x48;
    private static final int MAX_TYPES = 10_000;

    private NativeKeySwitch() {
    }

    /** Sets Fast-DDS's key flag on the type registered last under {@code name} on the participant. */
    static void enable(Participant participant, String name, int typeSize) throws DdsException {
        try {
            sun.misc.Unsafe u = unsafe();
            long impl = nativeParticipant(participant);
            long begin = u.getLong(impl + TYPES_BEGIN);
            long end = u.getLong(impl + TYPES_END);
            if (impl == 0 || begin == 0 || end < begin || (end - begin) % 16 != 0 || (end - begin) / 16 > MAX_TYPES) {
                throw unknownLayout(name, "no vector of registered types where expected");
            }
            byte[] expected = name.getBytes(StandardCharsets.UTF_8);
            for (long e = end - 16; e >= begin; e -= 16) { // each entry a std::shared_ptr: object, control block
                long type = u.getLong(e);
                if (type != 0 && u.getLong(type + NAME_LENGTH) == expected.length && nameIs(u, u.getLong(type + NAME_DATA), expected)) {
                    if (u.getInt(type + TYPE_SIZE) != typeSize) {
                        throw unknownLayout(name, "the native type's size is " + u.getInt(type + TYPE_SIZE) + ", not " + typeSize);
                    }
                    byte flag = u.getByte(type + GET_KEY_DEFINED);
                    if (flag != 0 && flag != 1) {
                        throw unknownLayout(name, "the byte where the key flag should be holds " + flag);
                    }
                    u.putByte(type + GET_KEY_DEFINED, (byte) 1);
                    return;
                }
            }
            throw unknownLayout(name, "the registered type was not found");
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            throw unknownLayout(name, e.toString());
        }
    }

    private static boolean nameIs(sun.misc.Unsafe u, long data, byte[] expected) {
        if (data == 0) {
            return false;
        }
        for (int i = 0; i < expected.length; i++) {
            if (u.getByte(data + i) != expected[i]) {
                return false;
            }
        }
        return u.getByte(data + expected.length) == 0;
    }

    /** The C++ address of the participant's {@code NativeParticipantImpl} (SWIG's pointer). */
    private static long nativeParticipant(Participant participant) throws ReflectiveOperationException {
        Field f = participant.getClass().getDeclaredField("impl");
        f.setAccessible(true);
        Object impl = f.get(participant);
        Method cPtr = impl.getClass().getDeclaredMethod("getCPtr", impl.getClass());
        cPtr.setAccessible(true);
        return (Long) cPtr.invoke(null, impl);
    }

    private static sun.misc.Unsafe unsafe() throws ReflectiveOperationException {
        Field f = sun.misc.Unsafe.class.getDeclaredField("theUnsafe");
        f.setAccessible(true);
        return (sun.misc.Unsafe) f.get(null);
    }

    private static DdsException unknownLayout(String name, String why) {
        return new DdsException("cannot make " + name + " keyed: the DDS library's native type is not laid out as in"
                + " ihmc-pub-sub 0.20.0 (" + why + "); use \"keyed\": false with peers that declare the type without a key", null);
    }
}
