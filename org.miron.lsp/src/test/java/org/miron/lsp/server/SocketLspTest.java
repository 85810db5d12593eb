package org.miron.lsp.server;

import static org.junit.Assert.assertTrue;

import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;

import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/** `--socket PORT`: the server listens on the loopback interface and serves a client that connects. */
public class SocketLspTest {

    @Test
    public void servesAClientOnLoopback() throws Exception {
        Path workspace = Examples.copy("intralogistics");
        try (ServerSocket listening = MironLanguageServer.bindLoopback(0)) {
            assertTrue(listening.getInetAddress().isLoopbackAddress());
            Thread acceptor = new Thread(() -> {
                try {
                    MironLanguageServer.acceptClients(listening);
                } catch (java.io.IOException closed) {
                    // The test closed the socket.
                }
            });
            acceptor.setDaemon(true);
            acceptor.start();
            try (Socket socket = new Socket(listening.getInetAddress(), listening.getLocalPort());
                    LspClient client = new LspClient(socket.getInputStream(), socket.getOutputStream())) {
                client.initialize(workspace);
                String uri = client.open(workspace.resolve("intralogistics.miron"));
                client.awaitDiagnostics(uri, d -> !IntralogisticsLspTest.hasErrors(d));
            }
        } finally {
            Folders.delete(workspace);
        }
    }

    /**
     * Issue 23, item 13: a client that disconnects in the middle of its requests leaves one line in
     * the server's log, no stack traces, and the server serves the next client.
     */
    @Test
    public void aDisconnectIsOneLineInTheLog() throws Exception {
        Path workspace = Examples.copy("intralogistics");
        java.io.File log = new java.io.File(workspace.toFile(), "server.log");
        java.util.List<String> command = new java.util.ArrayList<>(ProcessLspTest.serverCommand());
        command.addAll(java.util.List.of("--socket", "0"));
        Process process = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log)).start();
        try {
            int port = Integer.parseInt(awaitLog(log, "listening on 127.0.0.1:(\\d+)").group(1));
            Socket first = new Socket(java.net.InetAddress.getLoopbackAddress(), port);
            LspClient client = new LspClient(first.getInputStream(), first.getOutputStream());
            client.initialize(workspace);
            Path miron = workspace.resolve("intralogistics.miron");
            String text = java.nio.file.Files.readString(miron);
            String uri = client.open(miron, text.replace("roqme.safety++", "roqme.safetyy++"));
            client.awaitDiagnostics(uri, IntralogisticsLspTest::hasErrors);
            // Requests and changes in flight, then the connection drops without shutdown.
            for (int i = 0; i < 20; i++) {
                client.change(uri, text.replace("roqme.safety++", "roqme.safety" + i + "++"));
                client.server().getTextDocumentService().completion(new org.eclipse.lsp4j.CompletionParams(
                        new org.eclipse.lsp4j.TextDocumentIdentifier(uri), IntralogisticsLspTest.positionAfter(text, "affects ")));
            }
            first.close();
            awaitLog(log, "client " + first.getLocalPort() + " disconnected");

            try (Socket second = new Socket(java.net.InetAddress.getLoopbackAddress(), port);
                    LspClient next = new LspClient(second.getInputStream(), second.getOutputStream())) {
                next.initialize(workspace);
                next.awaitDiagnostics(next.open(miron), d -> !IntralogisticsLspTest.hasErrors(d));
            }
            String written = java.nio.file.Files.readString(log.toPath());
            assertTrue(written, !written.contains("SEVERE") && !written.contains("\tat ") && !written.contains("Broken pipe\n"));
        } finally {
            process.destroyForcibly();
            Folders.delete(workspace);
        }
    }

    /** The first match of a pattern in the log, once the server has written it. */
    private static java.util.regex.Matcher awaitLog(java.io.File log, String pattern) throws Exception {
        java.util.regex.Pattern wanted = java.util.regex.Pattern.compile(pattern);
        long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            java.util.regex.Matcher matcher = wanted.matcher(log.exists() ? java.nio.file.Files.readString(log.toPath()) : "");
            if (matcher.find()) {
                return matcher;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("no '" + pattern + "' in the server log within 60 s:\n"
                + (log.exists() ? java.nio.file.Files.readString(log.toPath()) : ""));
    }
}
