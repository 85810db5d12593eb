package org.miron.runtime.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.concurrent.SynchronousQueue;

import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * The JeroMQ behaviour behind the end-to-end tail (docs/performance.md), with nothing of MIRoN:
 * one PUSH socket sends a message over loopback TCP to a PULL socket in another thread, the
 * receiver hands the time back, and the next message leaves only then, so that JeroMQ's I/O
 * threads are asleep at every send (as on a bus with sporadic messages). Prints the latency
 * distribution and the CPU time of JeroMQ's I/O threads: with JeroMQ 0.6.0 the I/O threads spin
 * while a sender that signalled them is preempted before counting its signal
 * (zmq.Signaler.send writes, then increments), and the slow messages take whole scheduler ticks.
 * {@code gradle :org.miron.runtime:jeromqSignalRace [-Prounds=N] [-PprependClasses=DIR]}.
 */
public final class JeromqSignalRace {
    private JeromqSignalRace() {
    }

    /** The jar or folder a class was loaded from (-PprependClasses puts a rebuilt class first). */
    private static String origin(Class<?> type) {
        String location = type.getProtectionDomain().getCodeSource().getLocation().getPath();
        return location.substring(location.lastIndexOf('/', location.length() - 2) + 1);
    }

    public static void main(String[] args) throws Exception {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 3000;
        int warm = 500;
        long[] nanos = new long[rounds];
        SynchronousQueue<Long> received = new SynchronousQueue<>();
        try (ZContext context = new ZContext()) {
            ZMQ.Socket pull = context.createSocket(SocketType.PULL);
            int port = pull.bindToRandomPort("tcp://127.0.0.1");
            ZMQ.Socket push = context.createSocket(SocketType.PUSH);
            push.connect("tcp://127.0.0.1:" + port);
            Thread receiver = new Thread(() -> {
                try {
                    while (!Thread.currentThread().isInterrupted()) {
                        byte[] m = pull.recv(0);
                        if (m == null) {
                            return;
                        }
                        received.put(System.nanoTime());
                    }
                } catch (InterruptedException | org.zeromq.ZMQException e) {
                    // closing
                }
            }, "receiver");
            receiver.setDaemon(true);
            receiver.start();
            for (int i = -warm; i < rounds; i++) {
                long t0 = System.nanoTime();
                push.send(new byte[8], 0);
                long t1 = received.take();
                if (i >= 0) {
                    nanos[i] = t1 - t0;
                }
            }
            System.out.printf("%s (zmq.Signaler from %s), PUSH -> PULL over loopback TCP, one message at a time, "
                    + "%d messages:%n", origin(ZMQ.class), origin(Class.forName("zmq.Signaler")), rounds);
            long[] sorted = nanos.clone();
            Arrays.sort(sorted);
            System.out.printf("  latency p50 %.3f ms, p99 %.3f ms, max %.3f ms%n", sorted[rounds / 2] / 1e6,
                    sorted[(int) Math.ceil(rounds * 0.99) - 1] / 1e6, sorted[rounds - 1] / 1e6);
            int[] over = new int[4];
            for (long n : nanos) {
                for (int b = 0; b < 4; b++) {
                    if (n > (1_000_000L << b)) {
                        over[b]++;
                    }
                }
            }
            System.out.printf("  messages over 1 / 2 / 4 / 8 ms: %d / %d / %d / %d%n", over[0], over[1], over[2], over[3]);
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            for (long id : threads.getAllThreadIds()) {
                ThreadInfo info = threads.getThreadInfo(id);
                if (info != null && (info.getThreadName().startsWith("iothread") || info.getThreadName().equals("receiver")
                        || info.getThreadName().equals("main"))) {
                    System.out.printf("  CPU of thread %-12s %8.1f ms%n", info.getThreadName(), threads.getThreadCpuTime(id) / 1e6);
                }
            }
            receiver.interrupt();
        }
    }
}
