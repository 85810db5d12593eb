// MIRoN for VS Code: starts the MIRoN language server (`miron lsp`, over stdio) for behaviour
// trees, RoQME and MIRoN files, and offers "MIRoN: Generate" on .miron files.
import * as fs from 'fs';
import * as path from 'path';
import * as vscode from 'vscode';
import {
    ExecuteCommandRequest,
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

let client: LanguageClient | undefined;
let output: vscode.OutputChannel | undefined;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
    output = vscode.window.createOutputChannel('MIRoN Language Server');
    context.subscriptions.push(output);

    context.subscriptions.push(
        vscode.commands.registerCommand('miron.generate', (uri?: vscode.Uri) => generate(uri)),
        vscode.commands.registerCommand('miron.restartServer', () => restart(context)),
        vscode.commands.registerCommand('miron.showOutput', () => output?.show(true)),
        vscode.workspace.onDidChangeConfiguration(async (e) => {
            if (e.affectsConfiguration('miron.server')) {
                const choice = await vscode.window.showInformationMessage(
                    'The MIRoN language server settings changed.', 'Restart server');
                if (choice) {
                    await restart(context);
                }
            }
        }),
    );

    await start(context);
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

async function start(context: vscode.ExtensionContext): Promise<void> {
    const launch = currentLaunch();
    const executable: Executable = {
        command: launch.command,
        args: launch.args,
        // No `transport`: vscode-languageclient would append `--stdio`; `miron lsp` speaks stdio
        // by default.
        options: { cwd: launch.cwd, env: launch.env },
    };
    const serverOptions: ServerOptions = { run: executable, debug: executable };

    const watcher = vscode.workspace.createFileSystemWatcher(WATCHED_FILES);
    context.subscriptions.push(watcher);

    const clientOptions: LanguageClientOptions = {
        documentSelector: LANGUAGES.flatMap((language) => [
            { scheme: 'file', language },
            { scheme: 'untitled', language },
        ]),
        synchronize: { fileEvents: watcher },
        outputChannel: output,
        traceOutputChannel: output,
    };

    client = new LanguageClient('miron', 'MIRoN Language Server', serverOptions, clientOptions);
    output?.appendLine(`Starting ${[launch.command, ...launch.args].join(' ')}` +
        (launch.cwd ? ` in ${launch.cwd}` : ''));
    try {
        await client.start();
    } catch (err) {
        const hint = missingCommandHint(launch.command);
        const message = `MIRoN: the language server did not start (${errorText(err)}).${hint}`;
        output?.appendLine(message);
        const choice = await vscode.window.showErrorMessage(message, 'Open Settings', 'Show Output');
        if (choice === 'Open Settings') {
            await vscode.commands.executeCommand('workbench.action.openSettings', 'miron.server');
        } else if (choice === 'Show Output') {
            output?.show(true);
        }
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
}

async function restart(context: vscode.ExtensionContext): Promise<void> {
    await stop();
    await start(context);
}

/**
 * "MIRoN: Generate": asks the server to run `miron.generate` on a .miron file (the one given by
 * the explorer or editor menu, else the active editor's) and shows the message it answers.
 */
async function generate(uri?: vscode.Uri): Promise<void> {
    const target = uri instanceof vscode.Uri ? uri : vscode.window.activeTextEditor?.document.uri;
    if (!target || !target.path.endsWith('.miron')) {
        void vscode.window.showWarningMessage('MIRoN: Generate works on a .miron file: open one first.');
        return;
    }
    if (!client || !client.isRunning()) {
        void vscode.window.showErrorMessage('MIRoN: the language server is not running (see "MIRoN: Show Language Server Output").');
        return;
    }
    // Unsaved changes would not be what the generator reads from disk.
    const open = vscode.workspace.textDocuments.find((d) => d.uri.toString() === target.toString());
    if (open?.isDirty) {
        await open.save();
    }
    try {
        const result = await vscode.window.withProgress(
            { location: vscode.ProgressLocation.Notification, title: `MIRoN: generating ${path.basename(target.path)}` },
            () => client!.sendRequest(ExecuteCommandRequest.type, {
                command: 'miron.generate',
                arguments: [target.toString()],
            }));
        const { message, ok } = describeResult(result);
        if (ok) {
            void vscode.window.showInformationMessage(message);
        } else {
            void vscode.window.showErrorMessage(message);
        }
        output?.appendLine(message);
    } catch (err) {
        void vscode.window.showErrorMessage(`MIRoN: Generate failed: ${errorText(err)}`);
    }
}

function errorText(err: unknown): string {
    return err instanceof Error ? err.message : String(err);
}
