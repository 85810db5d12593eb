package org.miron.runtime;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.Arrays;

import org.junit.Test;

public class FreePortsTest {

    /** Free, distinct, and never a port the kernel could give an outgoing connection. */
    @Test
    public void portsAreFreeDistinctAndBelowTheEphemeralRange() throws Exception {
        int ephemeral = FreePorts.ephemeralStart();
        for (int round = 0; round < 20; round++) {
            int[] ports = FreePorts.take(5);
            assertEquals(Arrays.toString(ports), 5, Arrays.stream(ports).distinct().count());
            for (int port : ports) {
                assertTrue(port + " is in the ephemeral range from " + ephemeral, port >= 20_000 && port < ephemeral);
                try (ServerSocket bind = new ServerSocket(port, 1, InetAddress.getLoopbackAddress())) {
                    assertEquals(port, bind.getLocalPort());
                }
            }
        }
    }
}
