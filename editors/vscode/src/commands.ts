// "MIRoN: Generate" and "MIRoN: Convert to BehaviorTree.CPP 3/4": the server's workspace commands
// (miron.generate, miron.convert) as the user meets them, and Generate in a terminal when no
// server offers it.
import * as path from 'path';
import * as vscode from 'vscode';
import { describeResult } from './launch';
import { ServerMessages } from './messages';

/** How the commands reach the running server, and where they write. */
export interface CommandContext {
    messages: ServerMessages;
    output: vscode.OutputChannel;
    /** workspace/executeCommand on the running server, or undefined when none runs. */
    execute: ((command: string, args: unknown[]) => Thenable<unknown>) | undefined;
    /** The launch of the server's command line (for `miron generate` in a terminal). */
    launch: () => { command: string; args: string[]; cwd: string | undefined; env: NodeJS.ProcessEnv };
}

/**
 * The file a command works on: the one given by the explorer or editor menu (a Uri, or a URI
 * string when another extension or the server calls the command), else the active editor's.
 */
function targetOf(arg: unknown): vscode.Uri | undefined {
    if (arg instanceof vscode.Uri) {
        return arg;
    }
    if (typeof arg === 'string' && arg.length > 0) {
        return /^[a-z][a-z0-9+.-]*:/i.test(arg) && !/^[a-z]:[\\/]/i.test(arg) ? vscode.Uri.parse(arg) : vscode.Uri.file(arg);
    }
    return vscode.window.activeTextEditor?.document.uri;
}

async function saveIfDirty(target: vscode.Uri): Promise<void> {
    const open = vscode.workspace.textDocuments.find((d) => d.uri.toString() === target.toString());
    if (open?.isDirty) {
        await open.save();
    }
}

function generateTarget(arg: unknown): vscode.Uri | undefined {
    const target = targetOf(arg);
    if (!target || !/\.(miron|roqme)$/.test(target.path)) {
        void vscode.window.showWarningMessage('MIRoN: Generate works on a .miron (or .roqme) file: open one first.');
        return undefined;
    }
    return target;
}

/**
 * "MIRoN: Generate" through the server: workspace/executeCommand miron.generate with the file's
 * URI (a string). The answer is shown once (the server's own copy is held back), with "Open
 * generated files" when files were written, and goes to the status bar and the output.
 */
export async function generate(ctx: CommandContext, arg: unknown, execute: (uri: string) => Thenable<unknown>): Promise<unknown> {
    const target = generateTarget(arg);
    if (!target) {
        return undefined;
    }
    try {
        const result = await vscode.window.withProgress(
            { location: vscode.ProgressLocation.Notification, title: `MIRoN: generating ${path.basename(target.path)}` },
            () => ctx.messages.around(() => execute(target.toString()), (r) => describeResult(r).message));
        const { message, ok, errors, written } = describeResult(result);
        ctx.output.appendLine(message);
        errors.forEach((e) => ctx.output.appendLine(`  ${e}`));
        vscode.window.setStatusBarMessage(`${ok ? '$(check)' : '$(error)'} ${message}`, 10000);
        if (ok) {
            const actions = written.length > 0 ? ['Open generated files'] : [];
            void vscode.window.showInformationMessage(message, ...actions).then((choice) => {
                if (choice) {
                    void openFiles(written);
                }
            });
        } else {
            void vscode.window.showErrorMessage(message, 'Show Output').then((c) => c && ctx.output.show(true));
        }
        return result;
    } catch (err) {
        void vscode.window.showErrorMessage(`MIRoN: Generate failed: ${errorText(err)}`);
        return undefined;
    }
}

/** Opens the generated files in editors (the first, the woven tree, in front). */
async function openFiles(files: string[]): Promise<void> {
    const uris = files.map((f) => (/^[a-z][a-z0-9+.-]+:/i.test(f) ? vscode.Uri.parse(f) : vscode.Uri.file(f)));
    for (const uri of [...uris].reverse()) {
        try {
            await vscode.window.showTextDocument(uri, { preview: false, preserveFocus: uri !== uris[0] });
        } catch (err) {
            void vscode.window.showWarningMessage(`MIRoN: cannot open ${uri.fsPath}: ${errorText(err)}`);
        }
    }
}

/** "MIRoN: Generate" without a server offering it: `miron generate FILE` in a terminal. */
export async function generateInTerminal(ctx: CommandContext, arg: unknown): Promise<void> {
    const target = generateTarget(arg);
    if (!target) {
        return;
    }
    if (target.scheme !== 'file') {
        void vscode.window.showErrorMessage('MIRoN: Generate needs the language server for files that are not on disk.');
        return;
    }
    await saveIfDirty(target);
    const launch = ctx.launch();
    const args = [...launch.args.slice(0, -1), 'generate', target.fsPath];
    const terminal = vscode.window.createTerminal({ name: 'MIRoN: Generate', cwd: launch.cwd, env: launch.env });
    terminal.show();
    terminal.sendText([launch.command, ...args].map(shellQuote).join(' '));
}

/**
 * "MIRoN: Convert to BehaviorTree.CPP 3/4": miron.convert on the behaviour tree in the editor.
 * The server edits the document with workspace/applyEdit (undoable); its answer is shown once.
 */
export async function convert(ctx: CommandContext, version: '3' | '4', arg: unknown): Promise<void> {
    const target = targetOf(arg);
    const document = vscode.workspace.textDocuments.find((d) => d.uri.toString() === target?.toString());
    if (!target || (document ? document.languageId !== 'bt' : !/\.(bt|xml)$/.test(target.path))) {
        void vscode.window.showWarningMessage(`MIRoN: Convert to BehaviorTree.CPP ${version} works on a behaviour tree: open one first.`);
        return;
    }
    const execute = ctx.execute;
    if (!execute) {
        void vscode.window.showErrorMessage('MIRoN: Convert needs the language server, which is not running.', 'Show Output')
            .then((c) => c && ctx.output.show(true));
        return;
    }
    try {
        const result = await ctx.messages.around(() => execute('miron.convert', [target.toString(), version]),
            (r) => describeResult(r).message);
        const { message, ok, errors } = describeResult(result);
        ctx.output.appendLine(message);
        errors.forEach((e) => ctx.output.appendLine(`  ${e}`));
        if (ok) {
            void vscode.window.showInformationMessage(message);
        } else {
            void vscode.window.showErrorMessage(message, 'Show Output').then((c) => c && ctx.output.show(true));
        }
    } catch (err) {
        void vscode.window.showErrorMessage(`MIRoN: Convert failed: ${errorText(err)}`);
    }
}

function shellQuote(s: string): string {
    return /^[\w@%+=:,./-]+$/.test(s) ? s : `'${s.replace(/'/g, `'\\''`)}'`;
}

export function errorText(err: unknown): string {
    return err instanceof Error ? err.message : String(err);
}
