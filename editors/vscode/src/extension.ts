// MIRoN for VS Code: starts the MIRoN language server (`miron lsp`, over stdio) for behaviour
// trees, RoQME and MIRoN files, switches BehaviorTree.CPP `.xml` files to the BT language by their
// content, and offers "MIRoN: Generate", "MIRoN: Convert to BehaviorTree.CPP 3/4" and "MIRoN: Show
// Diagram" (src/diagram.ts).
import * as fs from 'fs';
import * as path from 'path';
import * as vscode from 'vscode';
import {
    CloseAction,
    ErrorAction,
    ErrorHandler,
    Executable,
    ExecuteCommandRequest,
    LanguageClient,
    LanguageClientOptions,
    ServerOptions,
    ShowMessageNotification,
    State,
} from 'vscode-languageclient/node';
import { CommandContext, convert, errorText, generate, generateInTerminal } from './commands';
import { isBehaviorTreeXml, mayBeBehaviorTree } from './detect';
import { DiagramPanels } from './diagram';
import { serverLaunch, ServerLaunch } from './launch';
import { ServerMessages } from './messages';
import { StatusItem } from './status';

/** The languages served by `miron lsp` (ids as contributed in package.json). */
export const LANGUAGES = ['bt', 'roqme', 'miron'] as const;

/** Files whose changes the server must hear about (imports across files, `.xml` trees). */
const WATCHED_FILES = '**/*.{bt,roqme,miron,xml}';

/** The workspace/executeCommand of `miron lsp` behind "MIRoN: Generate". */
const GENERATE = 'miron.generate';

/**
 * The client, quiet where the extension speaks itself: a failed start is reported once (by
 * `start`), not also by vscode-languageclient's own toast, and a server that exits with code 0
 * after `shutdown`/`exit` (every restart) is normal, not an error.
 */
class MironClient extends LanguageClient {
    quietStart = false;
    /** The first error of the current start, for the message when it fails. */
    startProblem: string | undefined;

    override error(message: string, data?: unknown, showNotification: boolean | 'force' = true): void {
        if (/^Server process exited with code 0\b/.test(message)) {
            this.info(message, data, false);
            return;
        }
        if (this.quietStart && (!this.startProblem || /exited with/.test(message))) {
            // The exit code says more than the failed request it caused.
            this.startProblem = message.replace(/\.$/, '');
        }
        super.error(message, data, this.quietStart ? false : showNotification);
    }
}

let client: MironClient | undefined;
let output: vscode.OutputChannel;
let status: StatusItem;
const messages = new ServerMessages();
/**
 * Our own `miron.generate` while no running server offers it. When the server offers the command,
 * vscode-languageclient registers the VS Code command of that name itself (and the middleware below
 * adapts its arguments and shows the answer), so the two registrations must never overlap.
 */
let fallbackGenerate: vscode.Disposable | undefined;
/** One watcher for the lifetime of the extension, shared by every (re)started client. */
let watcher: vscode.FileSystemWatcher | undefined;
/** Set while a start or a restart runs, so that two never overlap. */
let starting: Promise<void> | undefined;

const commandContext: CommandContext = {
    get messages() { return messages; },
    get output() { return output; },
    get execute() {
        const c = client;
        return c && c.state === State.Running
            ? (command: string, args: unknown[]) => c.sendRequest(ExecuteCommandRequest.type, { command, arguments: args })
            : undefined;
    },
    launch: () => currentLaunch(),
};

export async function activate(context: vscode.ExtensionContext): Promise<void> {
    output = vscode.window.createOutputChannel('MIRoN Language Server');
    status = new StatusItem();
    watcher = vscode.workspace.createFileSystemWatcher(WATCHED_FILES);
    context.subscriptions.push(output, status, watcher);
    const diagrams = new DiagramPanels(context.extensionUri, async () => {
        await ensureStarted();
        return client && client.state === State.Running ? client : undefined;
    });
    context.subscriptions.push(diagrams);

    context.subscriptions.push(
        vscode.commands.registerCommand('miron.restartServer', () => restart()),
        vscode.commands.registerCommand('miron.showOutput', () => output.show(true)),
        vscode.commands.registerCommand('miron.showDiagram', (uri?: unknown) => diagrams.show(uri)),
        vscode.commands.registerCommand('miron.convertTo3', (uri?: unknown) => convert(commandContext, '3', uri)),
        vscode.commands.registerCommand('miron.convertTo4', (uri?: unknown) => convert(commandContext, '4', uri)),
        vscode.workspace.onDidChangeConfiguration(async (e) => {
            if (e.affectsConfiguration('miron.server')) {
                const choice = await vscode.window.showInformationMessage(
                    'The MIRoN language server settings changed.', 'Restart server');
                if (choice) {
                    await restart();
                }
            }
        }),
        vscode.workspace.onDidOpenTextDocument((d) => onOpen(d)),
        vscode.workspace.onDidSaveTextDocument((d) => detectBehaviorTree(d)),
        { dispose: () => setFallbackGenerate(false) },
    );
    setFallbackGenerate(true);

    vscode.workspace.textDocuments.forEach((d) => detectBehaviorTree(d));
    // Activated by an .xml file only (onLanguage:xml), the server waits for a document it serves.
    const ours = vscode.workspace.textDocuments.some((d) => isOurs(d));
    if (ours || (await vscode.workspace.findFiles('**/*.{miron,roqme,bt}', '**/node_modules/**', 1)).length > 0) {
        await ensureStarted();
    }
}

export async function deactivate(): Promise<void> {
    await stop();
}

function isOurs(document: vscode.TextDocument): boolean {
    return (LANGUAGES as readonly string[]).includes(document.languageId);
}

function onOpen(document: vscode.TextDocument): void {
    detectBehaviorTree(document);
    if (isOurs(document)) {
        void ensureStarted();
    }
}

/**
 * An `.xml` file that is BehaviorTree.CPP XML (`<root>` with `<BehaviorTree>`) is switched to the
 * BT language, so the server checks it, without `files.associations`
 * (`miron.bt.detectXml`: false turns this off).
 */
function detectBehaviorTree(document: vscode.TextDocument): void {
    if (!mayBeBehaviorTree(document.languageId, document.uri.path)
        || !vscode.workspace.getConfiguration('miron', document.uri).get('bt.detectXml', true)
        || !isBehaviorTreeXml(document.getText())) {
        return;
    }
    output.appendLine(`${document.uri.fsPath || document.uri.toString()} is a behaviour tree: opened in the BT language.`);
    vscode.languages.setTextDocumentLanguage(document, 'bt').then(undefined,
        (err) => output.appendLine(`Cannot switch ${document.uri.toString()} to BT: ${errorText(err)}`));
}

/** `miron lsp` as the `miron.server.*` settings say. */
function currentLaunch(): ServerLaunch & { env: NodeJS.ProcessEnv } {
    const config = vscode.workspace.getConfiguration('miron.server');
    const folder = vscode.workspace.workspaceFolders?.find((f) => f.uri.scheme === 'file');
    const launch = serverLaunch(config.get('command', 'miron'), config.get('args', []), folder?.uri.fsPath);
    const env = { ...process.env, ...config.get<{ [key: string]: string }>('env', {}) };
    return { ...launch, env };
}

async function ensureStarted(): Promise<void> {
    if (client || starting) {
        return starting;
    }
    return restart();
}

async function restart(): Promise<void> {
    const previous = starting;
    const mine = (async () => {
        await previous;
        await stop();
        await start();
    })();
    starting = mine;
    try {
        await mine;
    } finally {
        if (starting === mine) {
            starting = undefined;
        }
    }
}

/**
 * After a crash the server is restarted up to 3 times in 3 minutes; then, or when it never got
 * going, it stays stopped and the user is told once.
 */
function errorHandler(): ErrorHandler {
    const restarts: number[] = [];
    return {
        error: (_error, _message, count) =>
            ({ action: (count ?? 0) <= 3 ? ErrorAction.Continue : ErrorAction.Shutdown, handled: true }),
        closed: () => {
            if (status.status !== 'running') {
                // Still starting: start() reports the failure.
                return { action: CloseAction.DoNotRestart, handled: true };
            }
            const now = Date.now();
            while (restarts.length > 0 && now - restarts[0] > 3 * 60 * 1000) {
                restarts.shift();
            }
            if (restarts.length < 3) {
                restarts.push(now);
                output.appendLine('The language server stopped unexpectedly: restarting it.');
                status.set('starting');
                return { action: CloseAction.Restart, handled: true };
            }
            const message = 'MIRoN: the language server stopped 4 times in 3 minutes and will not be restarted.';
            status.set('failed', 'crashed');
            reportFailure(message);
            return { action: CloseAction.DoNotRestart, handled: true };
        },
    };
}

async function start(): Promise<void> {
    const launch = currentLaunch();
    const executable: Executable = {
        command: launch.command,
        args: launch.args,
        // No `transport`: vscode-languageclient would append `--stdio`; `miron lsp` speaks stdio
        // by default.
        options: { cwd: launch.cwd, env: launch.env },
    };
    const serverOptions: ServerOptions = { run: executable, debug: executable };

    const clientOptions: LanguageClientOptions = {
        documentSelector: LANGUAGES.flatMap((language) => [
            { scheme: 'file', language },
            { scheme: 'untitled', language },
        ]),
        synchronize: watcher ? { fileEvents: watcher } : undefined,
        outputChannel: output,
        traceOutputChannel: output,
        errorHandler: errorHandler(),
        // No retry, and no message of vscode-languageclient's own: start() reports the failure.
        initializationFailedHandler: (error) => {
            output.appendLine(`The language server failed to initialize: ${errorText(error)}`);
            return false;
        },
        middleware: {
            executeCommand: (command, args, next) =>
                command === GENERATE ? generate(commandContext, args[0], (uri) => next(command, [uri])) : next(command, args),
        },
    };

    const c = new MironClient('miron', 'MIRoN Language Server', serverOptions, clientOptions);
    c.onNotification(ShowMessageNotification.type, (params) => messages.handle(params));
    c.onDidChangeState((e) => {
        if (client !== c) {
            return;
        }
        if (e.newState === State.Running) {
            status.set('running');
        } else if (e.newState === State.Starting) {
            status.set('starting');
        }
    });
    client = c;
    status.set('starting');
    output.appendLine(`Starting ${[launch.command, ...launch.args].join(' ')}` + (launch.cwd ? ` in ${launch.cwd}` : ''));
    c.quietStart = true;
    // vscode-languageclient registers miron.generate itself when the server offers it.
    setFallbackGenerate(false);
    try {
        await c.start();
        // vscode-languageclient 9 resolves start() when the server exits during initialize.
        if (c.state !== State.Running) {
            throw new Error(c.startProblem ?? 'the server stopped while starting');
        }
        c.quietStart = false;
        status.set('running');
        const commands = c.initializeResult?.capabilities.executeCommandProvider?.commands ?? [];
        if (!commands.includes(GENERATE)) {
            output.appendLine(`The server does not offer ${GENERATE}: "MIRoN: Generate" runs miron generate in a terminal.`);
            setFallbackGenerate(true);
        }
    } catch (err) {
        c.quietStart = false;
        setFallbackGenerate(true);
        status.set('failed', errorText(err));
        reportFailure(`MIRoN: the language server did not start (${errorText(err)}).${missingCommandHint(launch.command)}`);
    }
}

/** The one error message of a server that does not run, with the ways out. */
function reportFailure(message: string): void {
    output.appendLine(message);
    // Not awaited: activation must not wait for the user to close the message.
    void vscode.window.showErrorMessage(message, 'Open Settings', 'Show Output').then((choice) => {
        if (choice === 'Open Settings') {
            void vscode.commands.executeCommand('workbench.action.openSettings', 'miron.server');
        } else if (choice === 'Show Output') {
            output.show(true);
        }
    });
}

function setFallbackGenerate(on: boolean): void {
    if (on && !fallbackGenerate) {
        fallbackGenerate = vscode.commands.registerCommand(GENERATE, (uri?: unknown) => generateInTerminal(commandContext, uri));
    } else if (!on && fallbackGenerate) {
        fallbackGenerate.dispose();
        fallbackGenerate = undefined;
    }
}

function missingCommandHint(command: string): string {
    if (path.isAbsolute(command) && !fs.existsSync(command)) {
        return ` ${command} does not exist: set "miron.server.command".`;
    }
    return ' Set "miron.server.command" to the miron program (e.g. "./miron" in a source checkout).';
}

async function stop(): Promise<void> {
    const c = client;
    client = undefined;
    if (c) {
        c.quietStart = true; // a stop is not a failure to report
        try {
            if (c.state === State.Running) {
                await c.stop();
            }
        } catch (err) {
            output.appendLine(`Stopping the language server: ${errorText(err)}`);
        }
    }
    // vscode-languageclient drops its miron.generate with the stopped client.
    setFallbackGenerate(true);
    status?.set('stopped');
}
