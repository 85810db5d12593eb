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

/**
 * The message to show for the answer of `workspace/executeCommand` `miron.generate`: the server
 * answers a message string, or an object with a `message` (and maybe `files`, the written files,
 * and `success` or `ok` false when the models have errors).
 */
export function describeResult(result: unknown): { message: string; ok: boolean } {
    if (result === null || result === undefined) {
        return { message: 'MIRoN: Generate done.', ok: true };
    }
    if (typeof result === 'string') {
        return { message: result, ok: !/^\s*(error|failed)\b/i.test(result) };
    }
    if (typeof result === 'object') {
        const r = result as { message?: unknown; files?: unknown; success?: unknown; ok?: unknown };
        const ok = r.success !== false && r.ok !== false;
        let message = typeof r.message === 'string'
            ? r.message
            : ok ? 'MIRoN: Generate done.' : 'MIRoN: Generate failed.';
        if (Array.isArray(r.files) && r.files.length > 0 && typeof r.message !== 'string') {
            message += ` Wrote ${r.files.map((f) => path.basename(String(f))).join(', ')}.`;
        }
        return { message, ok };
    }
    return { message: String(result), ok: true };
}
