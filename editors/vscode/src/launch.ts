// Pure helpers of the extension (no `vscode` import), so the unit tests run them under plain Node.
import * as path from 'path';

/** How `miron lsp` is started. */
export interface ServerLaunch {
    command: string;
    args: string[];
    cwd: string | undefined;
}

/**
 * The launch of `miron lsp` from the settings: `command` is `miron.server.command` (a string, or
 * an array of the program and its first arguments), `args` is `miron.server.args`, `folder` the
 * first workspace folder. A relative path such as `./miron` is resolved against the folder; a bare
 * name (`miron`) is left to the PATH; `~/` is the home directory.
 */
export function serverLaunch(command: unknown, args: unknown, folder: string | undefined,
    home: string | undefined = process.env.HOME || process.env.USERPROFILE): ServerLaunch {
    const parts = (Array.isArray(command) ? command : [command])
        .filter((s) => s !== undefined && s !== null)
        .map((s) => String(s))
        .filter((s) => s.trim().length > 0);
    if (parts.length === 0) {
        parts.push('miron');
    }
    let program = parts[0];
    if (home && (program === '~' || program.startsWith('~/'))) {
        program = path.join(home, program.slice(1));
    }
    if (folder && !path.isAbsolute(program) && /[\\/]/.test(program)) {
        program = path.resolve(folder, program);
    }
    const extra = Array.isArray(args) ? args.map((a) => String(a)) : [];
    return { command: program, args: [...parts.slice(1), ...extra, 'lsp'], cwd: folder };
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
