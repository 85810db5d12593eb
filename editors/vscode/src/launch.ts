// Pure helpers of the extension (no `vscode` import), so the unit tests run them under plain Node.
import * as fs from 'fs';
import * as path from 'path';

/** How `miron lsp` is started. */
export interface ServerLaunch {
    command: string;
    args: string[];
    cwd: string | undefined;
}

/**
 * The launch of `miron lsp` from the settings: `command` is `miron.server.command` (a program, an
 * array of the program and its first arguments, or a command line in one string: split at white
 * space unless it names an existing file), `args` is `miron.server.args`, `folder` the
 * first workspace folder. A relative path such as `./miron` is resolved against the folder; a bare
 * name (`miron`) is left to the PATH; `~/` is the home directory.
 */
export function serverLaunch(command: unknown, args: unknown, folder: string | undefined,
    home: string | undefined = process.env.HOME || process.env.USERPROFILE,
    exists: (file: string) => boolean = fs.existsSync): ServerLaunch {
    let list: unknown[];
    if (Array.isArray(command)) {
        list = command;
    } else if (typeof command === 'string' && /\s/.test(command.trim()) && !exists(resolveProgram(command.trim(), folder, home))) {
        // A command line in one string: "java -jar /opt/miron/miron.jar", quotes group words.
        list = splitCommandLine(command);
    } else {
        list = [command];
    }
    const parts = list
        .filter((s) => s !== undefined && s !== null)
        .map((s) => String(s))
        .filter((s) => s.trim().length > 0);
    if (parts.length === 0) {
        parts.push('miron');
    }
    const program = resolveProgram(parts[0], folder, home);
    const extra = Array.isArray(args) ? args.map((a) => String(a)) : [];
    return { command: program, args: [...parts.slice(1), ...extra, 'lsp'], cwd: folder };
}

/** `~/x` in the home directory, `./x` or `dir/x` in the folder, a bare name left to the PATH. */
function resolveProgram(program: string, folder: string | undefined, home: string | undefined): string {
    let p = program;
    if (home && (p === '~' || p.startsWith('~/'))) {
        p = path.join(home, p.slice(1));
    }
    if (folder && !path.isAbsolute(p) && /[\\/]/.test(p)) {
        p = path.resolve(folder, p);
    }
    return p;
}

/** Splits a command line at white space; double or single quotes group words, \\ escapes. */
export function splitCommandLine(line: string): string[] {
    const words: string[] = [];
    let word = '';
    let inWord = false;
    let quote: string | undefined;
    for (let i = 0; i < line.length; i++) {
        const ch = line[i];
        if (quote) {
            if (ch === quote) {
                quote = undefined;
            } else if (ch === '\\' && quote === '"' && i + 1 < line.length) {
                word += line[++i];
            } else {
                word += ch;
            }
        } else if (ch === '"' || ch === "'") {
            quote = ch;
            inWord = true;
        } else if (ch === '\\' && i + 1 < line.length) {
            word += line[++i];
            inWord = true;
        } else if (/\s/.test(ch)) {
            if (inWord) {
                words.push(word);
            }
            word = '';
            inWord = false;
        } else {
            word += ch;
            inWord = true;
        }
    }
    if (inWord) {
        words.push(word);
    }
    return words;
}

/** What "MIRoN: Generate" tells the user about the answer of `miron.generate`. */
export interface GenerateOutcome {
    message: string;
    ok: boolean;
    /** The server has shown the message itself (window/showMessage): no second notification. */
    shownByServer: boolean;
    /** Problems that kept the generator from writing (`file:line:col: message`). */
    errors: string[];
    /** The files written (paths or URIs, as the server gives them). */
    written: string[];
}

/**
 * The outcome of workspace/executeCommand `miron.generate`. `miron lsp` answers
 * `{ ok, message, written, errors }` and shows the message itself (docs/lsp.md); a plain string
 * answer, or an object without a message, is shown by the extension.
 */
export function describeResult(result: unknown): GenerateOutcome {
    if (result === null || result === undefined) {
        return { message: 'MIRoN: Generate done.', ok: true, shownByServer: false, errors: [], written: [] };
    }
    if (typeof result === 'string') {
        return { message: result, ok: !/^\s*(error|failed|not generated)\b/i.test(result), shownByServer: false, errors: [], written: [] };
    }
    if (typeof result === 'object') {
        const r = result as { message?: unknown; written?: unknown; files?: unknown; errors?: unknown; success?: unknown; ok?: unknown };
        const errors = Array.isArray(r.errors) ? r.errors.map(String) : [];
        const ok = r.success !== false && r.ok !== false && (r.ok === true || errors.length === 0);
        const written = (Array.isArray(r.written) ? r.written : Array.isArray(r.files) ? r.files : []).map(String);
        if (typeof r.message === 'string') {
            return { message: r.message, ok, shownByServer: true, errors, written };
        }
        let message = ok ? 'MIRoN: Generate done.' : 'MIRoN: Generate failed.';
        if (written.length > 0) {
            message += ` Wrote ${written.map((f) => path.basename(String(f))).join(', ')}.`;
        }
        if (errors.length > 0) {
            message += ` ${errors[0]}${errors.length > 1 ? ` (and ${errors.length - 1} more)` : ''}`;
        }
        return { message, ok, shownByServer: false, errors, written };
    }
    return { message: String(result), ok: true, shownByServer: false, errors: [], written: [] };
}
