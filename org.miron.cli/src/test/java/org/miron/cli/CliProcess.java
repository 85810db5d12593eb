package org.miron.cli;

import java.io.File;
import java.util.ArrayList;
import java.util.List;

import org.zeromq.ZMQ;

import com.fasterxml.jackson.databind.ObjectMapper;

import picocli.CommandLine;

/** For the tests that run the command line as a real process ({@code java -cp … MironCli …}). */
public final class CliProcess {
    private CliProcess() {
    }

    /**
     * The jars of the classes the command line needs, wherever the test worker loaded them from,
     * then the worker's own class path for the rest (e.g. JeroMQ's jnacl).
     */
    public static String classpath() {
        List<String> parts = new ArrayList<>();
        for (Class<?> c : new Class<?>[] { MironCli.class, CommandLine.class, ZMQ.class, ObjectMapper.class,
                com.fasterxml.jackson.core.JsonFactory.class, com.fasterxml.jackson.annotation.JsonProperty.class }) {
            parts.add(c.getProtectionDomain().getCodeSource().getLocation().getPath());
        }
        parts.add(System.getProperty("java.class.path"));
        return String.join(File.pathSeparator, parts);
    }
}
