#!/usr/bin/env node
// A stand-in for `miron lsp` for the end-to-end test (test/e2e): speaks LSP over stdio with no
// dependencies, answers initialize, publishes one diagnostic per opened BT/RoQME/MIRoN document
// ("fake-miron: <file name> checked", a warning on the first line), one per file changed on disk
// (workspace/didChangeWatchedFiles: "fake-miron: <file name> changed on disk") and implements the
// workspace/executeCommand miron.generate (not with FAKE_MIRON_NO_GENERATE=1: it writes
// generated/<name>.ext.xml next to the model) and miron.convert (answers only). With
// FAKE_MIRON_FAIL=1 it exits at once with code 1, as a server that cannot start. Semantic tokens:
// a tree after `main.` and a property after `roqme.`.
// Usage: fake-miron.mjs lsp | generate FILE
import { appendFileSync, mkdirSync, writeFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

if (process.argv[2] === 'generate') {
    // What "MIRoN: Generate" runs in a terminal when the server does not offer miron.generate.
    process.stdout.write(`fake-miron: generated ${process.argv.slice(3).join(' ')} (command line)\n`);
    process.exit(0);
}
if (process.argv[2] !== 'lsp') {
    process.stderr.write('usage: fake-miron.mjs lsp | generate FILE\n');
    process.exit(2);
}
if (process.env.FAKE_MIRON_FAIL) {
    process.stderr.write('fake-miron: cannot start (FAKE_MIRON_FAIL)\n');
    process.exit(1);
}
// FAKE_MIRON_NO_GENERATE=1: a server without the miron.generate command.
const offerGenerate = !process.env.FAKE_MIRON_NO_GENERATE;
const log = (m) => { if (process.env.FAKE_MIRON_LOG) appendFileSync(process.env.FAKE_MIRON_LOG, m + '\n'); };

/** The open documents' texts (full synchronisation). */
const texts = new Map();

/**
 * Semantic tokens as miron lsp sends them for a tree after an alias (`main.Charge`: class) and a
 * RoQME property (`roqme.power_autonomy`: property), in LSP's relative encoding.
 */
function semanticTokens(text) {
    const data = [];
    let previousLine = 0;
    let previousStart = 0;
    text.split('\n').forEach((line, lineNo) => {
        for (const m of line.matchAll(/\b(?:main\.(\w+)|roqme\.(\w+))/g)) {
            const name = m[1] ?? m[2];
            const start = m.index + m[0].length - name.length;
            data.push(lineNo - previousLine, lineNo === previousLine ? start - previousStart : start, name.length, m[1] ? 0 : 1, 0);
            previousLine = lineNo;
            previousStart = start;
        }
    });
    return data;
}

function send(message) {
    const body = Buffer.from(JSON.stringify({ jsonrpc: '2.0', ...message }), 'utf8');
    process.stdout.write(`Content-Length: ${body.length}\r\n\r\n`);
    process.stdout.write(body);
}

function handle(msg) {
    log(`<- ${msg.method ?? 'response'} ${JSON.stringify(msg.params ?? msg.result ?? {}).slice(0, 300)}`);
    switch (msg.method) {
        case 'initialize':
            send({
                id: msg.id, result: {
                    capabilities: {
                        textDocumentSync: { openClose: true, change: 1 },
                        executeCommandProvider: { commands: offerGenerate ? ['miron.generate', 'miron.convert'] : ['miron.convert'] },
                        semanticTokensProvider: { legend: { tokenTypes: ['class', 'property'], tokenModifiers: [] }, full: true },
                    },
                    serverInfo: { name: 'fake-miron', version: '0' },
                },
            });
            break;
        case 'textDocument/semanticTokens/full':
            send({ id: msg.id, result: { data: semanticTokens(texts.get(msg.params.textDocument.uri) ?? '') } });
            break;
        case 'textDocument/didOpen':
        case 'textDocument/didChange': {
            const uri = msg.params.textDocument.uri;
            texts.set(uri, msg.params.textDocument.text ?? msg.params.contentChanges?.at(-1)?.text ?? '');
            const name = decodeURIComponent(uri.replace(/^.*\//, ''));
            send({
                method: 'textDocument/publishDiagnostics', params: {
                    uri, diagnostics: [{
                        range: { start: { line: 0, character: 0 }, end: { line: 0, character: 6 } },
                        severity: 2, source: 'miron', code: 'fake',
                        message: `fake-miron: ${name} checked (${msg.params.textDocument.languageId ?? 'changed'})`,
                    }],
                },
            });
            break;
        }
        case 'workspace/didChangeWatchedFiles':
            for (const change of msg.params.changes) {
                const name = decodeURIComponent(change.uri.replace(/^.*\//, ''));
                send({
                    method: 'textDocument/publishDiagnostics', params: {
                        uri: change.uri, diagnostics: [{
                            range: { start: { line: 0, character: 0 }, end: { line: 0, character: 1 } },
                            severity: 3, source: 'miron', code: 'fake',
                            message: `fake-miron: ${name} changed on disk (${['', 'created', 'changed', 'deleted'][change.type]})`,
                        }],
                    },
                });
            }
            break;
        case 'workspace/executeCommand':
        {
            // As miron lsp does (docs/lsp.md): shows the message and answers { ok, message, written, errors }.
            const [uri, version] = msg.params.arguments ?? [];
            const written = [];
            let message;
            if (msg.params.command === 'miron.convert') {
                message = `fake-miron: converted ${basename(uri)} to BehaviorTree.CPP ${version}`;
            } else {
                const model = fileURLToPath(uri);
                const file = join(dirname(model), 'generated', basename(model).replace(/\.miron$/, '.ext.xml'));
                mkdirSync(dirname(file), { recursive: true });
                writeFileSync(file, `<!-- fake-miron: generated from ${basename(model)} -->\n<root/>\n`);
                written.push(file);
                message = `fake-miron: generated ${uri}`;
            }
            send({ method: 'window/showMessage', params: { type: 3, message } });
            send({ id: msg.id, result: { ok: true, message, written, errors: [] } });
        }
            break;
        case 'shutdown':
            send({ id: msg.id, result: null });
            break;
        case 'exit':
            process.exit(0);
            break;
        default:
            if (msg.id !== undefined && msg.method) {
                send({ id: msg.id, error: { code: -32601, message: `not supported: ${msg.method}` } });
            }
    }
}

let buffer = Buffer.alloc(0);
process.stdin.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    for (;;) {
        const headerEnd = buffer.indexOf('\r\n\r\n');
        if (headerEnd < 0) return;
        const length = Number(/Content-Length: *(\d+)/i.exec(buffer.subarray(0, headerEnd).toString())?.[1]);
        if (buffer.length < headerEnd + 4 + length) return;
        const body = buffer.subarray(headerEnd + 4, headerEnd + 4 + length).toString('utf8');
        buffer = buffer.subarray(headerEnd + 4 + length);
        handle(JSON.parse(body));
    }
});
process.stdin.on('end', () => process.exit(0));
