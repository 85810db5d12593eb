package org.miron.eclipse.tests;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/** A minimal JSON-RPC client over LSP's base protocol (Content-Length framed messages). */
final class Lsp {
    private Lsp() {
    }

    /** Sends a request and answers the raw JSON of its response (skipping other messages). */
    static String request(OutputStream out, InputStream in, int id, String method, String params) throws IOException {
        String json = "{\"jsonrpc\":\"2.0\",\"id\":" + id + ",\"method\":\"" + method + "\",\"params\":" + params + "}";
        byte[] body = json.getBytes(StandardCharsets.UTF_8);
        out.write(("Content-Length: " + body.length + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
        out.write(body);
        out.flush();
        while (true) {
            String message = read(in);
            if (message.contains("\"id\":" + id) && (message.contains("\"result\"") || message.contains("\"error\""))) {
                return message;
            }
        }
    }

    private static String read(InputStream in) throws IOException {
        int length = -1;
        StringBuilder line = new StringBuilder();
        while (true) {
            int c = in.read();
            if (c < 0) {
                throw new EOFException("the server closed the connection");
            }
            if (c == '\n') {
                String header = line.toString().trim();
                if (header.isEmpty()) {
                    break;
                }
                if (header.toLowerCase().startsWith("content-length:")) {
                    length = Integer.parseInt(header.substring("content-length:".length()).trim());
                }
                line.setLength(0);
            } else {
                line.append((char) c);
            }
        }
        return new String(in.readNBytes(length), StandardCharsets.UTF_8);
    }
}
