// Tokenizes text with the extension's TextMate grammars, as VS Code does (vscode-textmate with the
// Oniguruma WebAssembly build), offline.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const require = createRequire(import.meta.url);
const vsctm = require('vscode-textmate');
const oniguruma = require('vscode-oniguruma');

export const extensionRoot = join(dirname(fileURLToPath(import.meta.url)), '..');
export const repoRoot = join(extensionRoot, '..', '..');
export const manifest = JSON.parse(readFileSync(join(extensionRoot, 'package.json'), 'utf8'));

const grammarFiles = Object.fromEntries(
    manifest.contributes.grammars.map((g) => [g.scopeName, join(extensionRoot, g.path)]));

let registry;
function getRegistry() {
    if (!registry) {
        const wasm = readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm'));
        const onigLib = oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength))
            .then(() => ({
                createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
                createOnigString: (s) => new oniguruma.OnigString(s),
            }));
        registry = new vsctm.Registry({
            onigLib,
            loadGrammar: async (scopeName) => {
                const file = grammarFiles[scopeName];
                return file ? vsctm.parseRawGrammar(readFileSync(file, 'utf8'), file) : null;
            },
        });
    }
    return registry;
}

/** The scope name of a language id, from package.json. */
export function scopeOf(language) {
    return manifest.contributes.grammars.find((g) => g.language === language).scopeName;
}

/** Tokens of `text`: [{ line (0-based), text, scopes }]. */
export async function tokenize(language, text) {
    const grammar = await getRegistry().loadGrammar(scopeOf(language));
    if (!grammar) throw new Error(`no grammar for ${language}`);
    const tokens = [];
    let state = vsctm.INITIAL;
    text.split(/\r?\n/).forEach((line, index) => {
        const result = grammar.tokenizeLine(line, state);
        for (const t of result.tokens) {
            tokens.push({ line: index, lineText: line, text: line.substring(t.startIndex, t.endIndex), scopes: t.scopes });
        }
        state = result.ruleStack;
    });
    return tokens;
}

export async function tokenizeFile(language, file) {
    return tokenize(language, readFileSync(file, 'utf8'));
}
