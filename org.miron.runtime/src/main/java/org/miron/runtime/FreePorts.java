package org.miron.runtime;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Loopback ports free right now, taken below the kernel's ephemeral range. A port from that range
 * (what binding port 0 hands out) can be given to an outgoing connection between the probe and the
 * real bind; worse, a ZeroMQ peer that keeps reconnecting to a port nothing listens on yet can be
 * given that very port as its own and connect to itself (TCP's simultaneous open), and the
 * server's bind then fails. Ports below the range are never handed out that way.
 */
public final class FreePorts {
    /** Below this, well-known services; the choice is among the ports from here to the ephemeral range. */
    private static final int LOWEST = 20_000;
    /** Where Linux's ephemeral range starts by default (net.ipv4.ip_local_port_range). */
    private static final int LINUX_DEFAULT_EPHEMERAL = 32_768;
    private static final Path RANGE = Path.of("/proc/sys/net/ipv4/ip_local_port_range");

    private FreePorts() {
    }

    /**
     * {@code count} distinct ports free on loopback now. All probe sockets stay open until every
     * port is chosen, so one port is never handed out twice.
     */
    public static int[] take(int count) {
        int highest = ephemeralStart() - 1;
        List<ServerSocket> probes = new ArrayList<>();
        try {
            if (highest - LOWEST < 1000) { // an unusual ephemeral range: let the kernel choose
                for (int i = 0; i < count; i++) {
                    probes.add(new ServerSocket(0, 1, InetAddress.getLoopbackAddress()));
                }
            }
            for (int attempt = 0; probes.size() < count; attempt++) {
                int port = ThreadLocalRandom.current().nextInt(LOWEST, highest + 1);
                try {
                    probes.add(new ServerSocket(port, 1, InetAddress.getLoopbackAddress()));
                } catch (java.net.BindException taken) {
                    if (attempt > 1000) {
                        throw new IOException("no free loopback port between " + LOWEST + " and " + highest, taken);
                    }
                }
            }
            return probes.stream().mapToInt(ServerSocket::getLocalPort).toArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            for (ServerSocket probe : probes) {
                try {
                    probe.close();
                } catch (IOException e) {
                    // a probe that cannot close leaves its port taken; the bind will say so
                }
            }
        }
    }

    /** The first port of the kernel's ephemeral range (Linux's file; its default elsewhere). */
    static int ephemeralStart() {
        try {
            // read by lines: Files.readString reads "3" of "32768\t60999" from procfs (JDK 17)
            String[] range = Files.readAllLines(RANGE).get(0).trim().split("\\s+");
            return Integer.parseInt(range[0]);
        } catch (IOException | RuntimeException unreadable) {
            return LINUX_DEFAULT_EPHEMERAL;
        }
    }
}
