package org.miron.lsp.server;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;

import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.xtext.ide.server.LanguageServerImpl;

import com.google.inject.Guice;

/**
 * The MIRoN language server for .bt/.xml, .roqme and .miron files, over stdio (the default) or,
 * with {@code --socket PORT}, over a loopback socket (one server per client connection).
 */
public final class MironLanguageServer {

    private MironLanguageServer() {
    }

    /** Serves one client on the given streams; the future ends when the input closes. */
    public static Future<Void> serve(InputStream in, OutputStream out, boolean exitProcess) {
        StartupLog.mark("server starting");
        MironLanguages.setUpAhead(); // while Guice creates the server's injector
        DisconnectLogFilter.install();
        LanguageServerImpl server = Guice.createInjector(MironServerModule.create(exitProcess))
                .getInstance(LanguageServerImpl.class);
        Launcher<LanguageClient> launcher = Launcher.createLauncher(server, LanguageClient.class, in, out);
        server.connect(StartupLog.watch(launcher.getRemoteProxy()));
        if (server instanceof MironLanguageServerImpl miron) {
            miron.connectDiagrams(launcher.getRemoteEndpoint()::notify);
        }
        StartupLog.mark("server listening");
        return launcher.startListening();
    }

    /** Serves stdin/stdout until the client exits; anything else written to stdout goes to stderr. */
    public static void serveStdio() throws InterruptedException {
        PrintStream protocol = System.out;
        System.setOut(System.err);
        try {
            serve(System.in, protocol, true).get();
        } catch (ExecutionException e) {
            System.err.println("miron lsp: connection ended: " + e.getCause());
        }
    }

    /** Accepts clients on 127.0.0.1:port until the process is stopped. */
    public static void serveSocket(int port) throws IOException {
        try (ServerSocket socket = bindLoopback(port)) {
            System.err.println("miron lsp: listening on " + socket.getInetAddress().getHostAddress() + ":"
                    + socket.getLocalPort());
            acceptClients(socket);
        }
    }

    /** A server socket on the loopback interface only: the server reads and writes the user's files. */
    public static ServerSocket bindLoopback(int port) throws IOException {
        return new ServerSocket(port, 50, InetAddress.getLoopbackAddress());
    }

    /** Serves each client that connects, each with its own server, until the socket closes. */
    public static void acceptClients(ServerSocket socket) throws IOException {
        while (!socket.isClosed()) {
            Socket client = socket.accept();
            Thread thread = new Thread(() -> serveClient(client), "miron-lsp-" + client.getPort());
            thread.setDaemon(true);
            thread.start();
        }
    }

    private static void serveClient(Socket client) {
        try (client) {
            serve(client.getInputStream(), client.getOutputStream(), false).get();
            System.err.println("miron lsp: client " + client.getPort() + " disconnected");
        } catch (IOException | ExecutionException e) {
            // A disconnect is normal: one line, never a stack trace (DisconnectLogFilter).
            Throwable cause = e instanceof ExecutionException && e.getCause() != null ? e.getCause() : e;
            System.err.println("miron lsp: client " + client.getPort() + " disconnected (" + cause.getMessage() + ")");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Stand-alone entry point, the same as `miron lsp [--socket PORT]`. */
    public static void main(String[] args) throws Exception {
        if (args.length == 2 && args[0].equals("--socket") && args[1].matches("\\d{1,5}")
                && Integer.parseInt(args[1]) <= 65535) {
            serveSocket(Integer.parseInt(args[1]));
        } else if (args.length == 0) {
            serveStdio();
            System.exit(0);
        } else {
            System.err.println("usage: MironLanguageServer [--socket PORT]");
            System.exit(2);
        }
    }
}
