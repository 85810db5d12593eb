package org.miron.cli;

import java.util.concurrent.CountDownLatch;

/**
 * Keeps a command alive until SIGTERM/Ctrl-C (never by reading stdin), then closes the running
 * component from the shutdown hook so sockets and the ZContext are released before the JVM exits.
 */
final class UntilShutdown {
    private UntilShutdown() {
    }

    static int run(String name, AutoCloseable component) {
        CountDownLatch closed = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            try {
                component.close();
            } catch (Exception e) {
                System.err.println("miron " + name + ": error while stopping: " + e.getMessage());
            } finally {
                closed.countDown();
            }
        }, "miron-" + name + "-shutdown");
        try {
            Runtime.getRuntime().addShutdownHook(hook);
        } catch (IllegalStateException e) { // SIGTERM came while the component was starting
            hook.run();
            return 0;
        }
        try {
            closed.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            Runtime.getRuntime().removeShutdownHook(hook);
            hook.run();
        }
        return 0;
    }
}
