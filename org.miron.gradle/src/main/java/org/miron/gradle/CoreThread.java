package org.miron.gradle;

import java.util.concurrent.Callable;

/**
 * Runs the core as the command line does: on a thread with the stack `./miron` gives its JVM
 * (-Xss4m; the BT grammar's backtracking parser recurses once per nesting level, and a Gradle
 * worker thread's default stack overflows on a few thousand levels), and one run at a time. The
 * languages are set up in statics of this plugin's class loader (EMF's package registry, the
 * injectors), which the projects of a build that take the plugin from the same class path share:
 * under --parallel, their checkMiron and generateMiron take turns rather than set them up together.
 * A thread per run also ends the core's thread-locals with the run, instead of leaving them on the
 * daemon's long-lived threads.
 */
final class CoreThread {
    private static final long STACK_BYTES = 4L << 20;
    private static final Object LOCK = new Object();

    private CoreThread() {
    }

    static <T> T call(Callable<T> work) {
        Object[] result = new Object[1];
        Throwable[] failure = new Throwable[1];
        Thread thread = new Thread(null, () -> {
            try {
                result[0] = work.call();
            } catch (Throwable t) {
                failure[0] = t;
            }
        }, "miron-core", STACK_BYTES);
        thread.setContextClassLoader(CoreThread.class.getClassLoader());
        synchronized (LOCK) {
            thread.start();
            try {
                thread.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while the MIRoN core ran", e);
            }
        }
        if (failure[0] instanceof RuntimeException) {
            throw (RuntimeException) failure[0];
        }
        if (failure[0] instanceof Error) {
            throw (Error) failure[0];
        }
        if (failure[0] != null) {
            throw new IllegalStateException(failure[0]);
        }
        @SuppressWarnings("unchecked")
        T value = (T) result[0];
        return value;
    }
}
