// MIRoN for VS Code: starts the MIRoN language server (`miron lsp`, over stdio) for behaviour
// trees, RoQME and MIRoN files, and offers "MIRoN: Generate" on .miron files.
import * as fs from 'fs';
import * as path from 'path';
import * as vscode from 'vscode';
import {
    Executable,
    LanguageClient,
    LanguageClientOptions,
    ServerOptions,
    State,
} from 'vscode-languageclient/node';
import { describeResult, serverLaunch, ServerLaunch } from './launch';

/** The languages served by `miron lsp` (ids as contributed in package.json). */
export const LANGUAGES = ['bt', 'roqme', 'miron'] as const;

/** Files whose changes the server must hear about (imports across files, `.xml` trees). */
const WATCHED_FILES = '**/*.{bt,roqme,miron,xml}';

/** The workspace/executeCommand of `miron lsp` behind "MIRoN: Generate". */
const GENERATE = 'miron.generate';

let client: LanguageClient | undefined;
let output: vscode.OutputChannel | undefined;
/**
 * Our own `miron.generate` while no running server offers it. When the server offers the command,
 * vscode-languageclient registers the VS Code command of that name itself (and the middleware below
 * adapts its arguments and shows the answer), so the two registrations must never overlap.
 */
let fallbackGenerate: vscode.Disposable | undefined;
/** One watcher for the lifetime of the extension, shared by every (re)started client. */
let watcher: vscode.FileSystemWatcher | undefined;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
    output = vscode.window.createOutputChannel('MIRoN Language Server');
    watcher = vscode.workspace.createFileSystemWatcher(WATCHED_FILES);
    context.subscriptions.push(output, watcher);

    context.subscriptions.push(
        vscode.commands.registerCommand('miron.restartServer', () => restart()),
        vscode.commands.registerCommand('miron.showOutput', () => output?.show(true)),
        vscode.workspace.onDidChangeConfiguration(async (e) => {
            if (e.affectsConfiguration('miron.server')) {
                const choice = await vscode.window.showInformationMessage(
                    'The MIRoN language server settings changed.', 'Restart server');
                if (choice) {
                    await restart();
                }
            }
        }),
        { dispose: () => setFallbackGenerate(false) },
    );

    await start();
}

export async function deactivate(): Promise<void> {
    await stop();
}

/** `miron lsp` as the `miron.server.*` settings say. */
function currentLaunch(): ServerLaunch & { env: NodeJS.ProcessEnv } {
    const config = vscode.workspace.getConfiguration('miron.server');
    const folder = vscode.workspace.workspaceFolders?.find((f) => f.uri.scheme === 'file');
    const launch = serverLaunch(config.get('command', 'miron'), config.get('args', []), folder?.uri.fsPath);
    const env = { ...process.env, ...config.get<{ [key: string]: string }>('env', {}) };
    return { ...launch, env };
}

async function start(): Promise<void> {
    setFallbackGenerate(false);
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
        middleware: {
            executeCommand: (command, args, next) =>
                command === GENERATE ? generate(args[0], (uri) => next(command, [uri])) : next(command, args),
        },
    };

    client = new LanguageClient('miron', 'MIRoN Language Server', serverOptions, clientOptions);
    output?.appendLine(`Starting ${[launch.command, ...launch.args].join(' ')}` +
        (launch.cwd ? ` in ${launch.cwd}` : ''));
    try {
        await client.start();
        const commands = client.initializeResult?.capabilities.executeCommandProvider?.commands ?? [];
        if (!commands.includes(GENERATE)) {
            output?.appendLine(`The server does not offer ${GENERATE}: "MIRoN: Generate" runs miron generate in a terminal.`);
            setFallbackGenerate(true);
        }
    } catch (err) {
        setFallbackGenerate(true);
        const hint = missingCommandHint(launch.command);
        const message = `MIRoN: the language server did not start (${errorText(err)}).${hint}`;
        output?.appendLine(message);
        // Not awaited: activation must not wait for the user to close the message.
        void vscode.window.showErrorMessage(message, 'Open Settings', 'Show Output').then((choice) => {
            if (choice === 'Open Settings') {
                void vscode.commands.executeCommand('workbench.action.openSettings', 'miron.server');
            } else if (choice === 'Show Output') {
                output?.show(true);
            }
        });
    }
}

function setFallbackGenerate(on: boolean): void {
    if (on && !fallbackGenerate) {
        fallbackGenerate = vscode.commands.registerCommand(GENERATE, (uri?: unknown) => generateInTerminal(uri));
    } else if (!on && fallbackGenerate) {
        fallbackGenerate.dispose();
        fallbackGenerate = undefined;
    }
}

function missingCommandHint(command: string): string {
    if (path.isAbsolute(command) && !fs.existsSync(command)) {
        return ` ${command} does not exist: set "miron.server.command".`;
    }
    return ' Set "miron.server.command" to the miron command line (e.g. "./miron" in a source checkout).';
}

async function stop(): Promise<void> {
    const c = client;
    client = undefined;
    if (c && c.state !== State.Stopped) {
        try {
            await c.stop();
        } catch (err) {
            output?.appendLine(`Stopping the language server: ${errorText(err)}`);
        }
    }
    setFallbackGenerate(true);
}

async function restart(): Promise<void> {
    await stop();
    await start();
}

/**
 * The .miron file "MIRoN: Generate" works on: the one given by the explorer or editor menu (a
 * Uri, or a URI string when another extension or the server calls the command), else the
 * active editor's. With `save`, saves unsaved changes first (for `miron generate` on the command
 * line, which reads the file; the server generates the model as the editor has it).
 */
async function generateTarget(arg: unknown, save: boolean): Promise<vscode.Uri | undefined> {
    let target: vscode.Uri | undefined;
    if (arg instanceof vscode.Uri) {
        target = arg;
    } else if (typeof arg === 'string' && arg.length > 0) {
        target = /^[a-z][a-z0-9+.-]*:/i.test(arg) && !/^[a-z]:[\\/]/i.test(arg) ? vscode.Uri.parse(arg) : vscode.Uri.file(arg);
    } else {
        target = vscode.window.activeTextEditor?.document.uri;
    }
    if (!target || !target.path.endsWith('.miron')) {
        void vscode.window.showWarningMessage('MIRoN: Generate works on a .miron file: open one first.');
        return undefined;
    }
    const open = vscode.workspace.textDocuments.find((d) => d.uri.toString() === target!.toString());
    if (save && open?.isDirty) {
        await open.save();
    }
    return target;
}

/**
 * "MIRoN: Generate" through the server: sends workspace/executeCommand miron.generate with the
 * file's URI (as a string); the answer goes to the status bar and the output, and to a
 * notification unless the server showed it.
 */
async function generate(arg: unknown, execute: (uri: string) => Promise<unknown>): Promise<unknown> {
    const target = await generateTarget(arg, false);
    if (!target) {
        return undefined;
    }
    try {
        const result = await vscode.window.withProgress(
            { location: vscode.ProgressLocation.Notification, title: `MIRoN: generating ${path.basename(target.path)}` },
            () => execute(target.toString()));
        const { message, ok, shownByServer, errors } = describeResult(result);
        output?.appendLine(message);
        errors.forEach((e) => output?.appendLine(`  ${e}`));
        vscode.window.setStatusBarMessage(`${ok ? '$(check)' : '$(error)'} ${message}`, 10000);
        if (!shownByServer) {
            if (ok) {
                void vscode.window.showInformationMessage(message);
            } else {
                void vscode.window.showErrorMessage(message, 'Show Output').then((c) => c && output?.show(true));
            }
        }
        return result;
    } catch (err) {
        void vscode.window.showErrorMessage(`MIRoN: Generate failed: ${errorText(err)}`);
        return undefined;
    }
}

/** "MIRoN: Generate" without a server offering it: `miron generate FILE` in a terminal. */
async function generateInTerminal(arg: unknown): Promise<void> {
    const target = await generateTarget(arg, true);
    if (!target) {
        return;
    }
    if (target.scheme !== 'file') {
        void vscode.window.showErrorMessage('MIRoN: Generate needs the language server for files that are not on disk.');
        return;
    }
    const launch = currentLaunch();
    const args = [...launch.args.slice(0, -1), 'generate', target.fsPath];
    const terminal = vscode.window.createTerminal({ name: 'MIRoN: Generate', cwd: launch.cwd, env: launch.env });
    terminal.show();
    terminal.sendText([launch.command, ...args].map(shellQuote).join(' '));
}

function shellQuote(s: string): string {
    return /^[\w@%+=:,./-]+$/.test(s) ? s : `'${s.replace(/'/g, `'\\''`)}'`;
}

function errorText(err: unknown): string {
    return err instanceof Error ? err.message : String(err);
}
