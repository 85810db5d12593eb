package org.miron.dds;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;

/**
 * Runs one public method of {@link DdsScenarios} in this JVM and exits 0 when it returns, 1 when it
 * throws (the stack trace on stderr). DdsBridgeTest starts this JVM inside a private network
 * namespace holding only {@code lo}; the Gradle test worker itself cannot go there (it talks to
 * Gradle over the host's loopback).
 */
public final class NetnsMain {
    private NetnsMain() {
    }

    public static void main(String[] args) throws Exception {
        int status = 1;
        java.nio.file.Path dir = java.nio.file.Files.createTempDirectory("dds-scenario");
        try {
            Method m = DdsScenarios.class.getMethod(args[0], java.nio.file.Path.class);
            m.invoke(new DdsScenarios(), dir);
            System.out.println("scenario " + args[0] + ": passed");
            status = 0;
        } catch (InvocationTargetException e) {
            System.err.println("scenario " + args[0] + ": FAILED");
            e.getCause().printStackTrace();
        } catch (Throwable t) {
            System.err.println("scenario " + args[0] + ": could not run");
            t.printStackTrace();
        }
        System.out.flush();
        System.err.flush();
        Runtime.getRuntime().halt(status); // no shutdown hooks: the native DDS threads never block the exit
    }
}
