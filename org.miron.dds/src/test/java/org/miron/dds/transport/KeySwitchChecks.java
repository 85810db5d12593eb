package org.miron.dds.transport;

import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.lang.reflect.Field;
import java.net.InetAddress;
import java.util.List;
import us.ihmc.pubsub.participant.Participant;

/**
 * {@link NativeKeySwitch} on a real participant: it writes only into the native type it was asked
 * for, and refuses, saying why, whatever does not look like it. Run by DdsScenarios (a DDS
 * participant belongs in the tests' network namespace).
 */
public final class KeySwitchChecks {
    private KeySwitchChecks() {
    }

    public static void run() throws Exception {
        try (IhmcTransport dds = new IhmcTransport(0, "key-switch-checks", List.of(InetAddress.getByName("127.0.0.1")))) {
            Field f = IhmcTransport.class.getDeclaredField("participant");
            f.setAccessible(true);
            Participant participant = (Participant) f.get(dds);
            Qos q = Qos.DEFAULT;
            dds.writer(new TopicSpec("RoqmeEstimate", "RoqmeEstimate", q, List.of("p"), false)).close(); // registers it unkeyed
            int size = Types.lookup("RoqmeEstimate", false).getTypeSize();
            refused(() -> NativeKeySwitch.enable(participant, "RoqmeDDSTopics::RoqmeNothing", size), "the registered type was not found");
            refused(() -> NativeKeySwitch.enable(participant, "RoqmeDDSTopics::RoqmeEstimat", size), "the registered type was not found");
            refused(() -> NativeKeySwitch.enable(participant, "RoqmeDDSTopics::RoqmeEstimate", size + 1), "the native type's size is " + size);
            refused(() -> dds.writer(new TopicSpec("RoqmeEstimate", "RoqmeEstimate", q, List.of("p"), true)), "already used unkeyed");
            refused(() -> dds.writer(new TopicSpec("rt/x", "std_msgs/String", q, List.of(), true)), "std_msgs/String has no key");
            // a keyed type next to it on the same participant: created, and its writer too
            dds.writer(new TopicSpec("RoqmeDoubleContext", "RoqmeDoubleContext", q, List.of("p"), true)).close();
        }
    }

    interface Call {
        void run() throws Exception;
    }

    private static void refused(Call c, String why) throws Exception {
        try {
            c.run();
            fail("expected a refusal: " + why);
        } catch (DdsException e) {
            assertTrue(e.getMessage(), e.getMessage().contains(why));
        }
    }
}
