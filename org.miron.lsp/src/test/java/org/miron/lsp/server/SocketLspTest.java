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
}
