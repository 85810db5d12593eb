#!/usr/bin/env node
// End-to-end test in a real VS Code: starts code-server on loopback (no auth) with the packaged
// extension installed, opens a copy of examples/intralogistics in headless Chromium and checks
// that the languages are recognised (status bar language mode), the language server's diagnostics
// reach the Problems view and "MIRoN: Generate" answers.
//
//   npm run test:e2e
//
// Environment:
//   CODE_SERVER     the code-server executable (default: code-server on the PATH, else
//                   /tmp/code-server/node_modules/.bin/code-server from install-code-server.sh)
//   CHROMIUM        the Chromium executable (default: /usr/bin/chromium)
//   MIRON_VSIX      the extension (default: build/miron-vscode.vsix; build it with npm run package)
//   MIRON_SERVER    JSON array or string for miron.server.command (default: test/fake-miron.mjs, a
//                   stand-in server publishing one warning per file; /path/to/repo/miron for the
//                   real one: then a rule naming an unknown property is appended to the copy of
//                   intralogistics.miron)
//   MIRON_DIAGNOSTIC  text expected in the Problems view (default: the stand-in's message, or
//                   "nonexistent" with the real server)
//   MIRON_GENERATED   text expected in the notification of MIRoN: Generate (default: generated)
// The checks of the .roqme/.bt diagnostics and of the watched files need the stand-in server.
// Writes screenshots and the code-server log to build/e2e/. Prints "N passed, N failed" and
// JUnit XML (MIRON_JUNIT_XML, default ../build/test-results/test/TEST-vscode-e2e.xml).
import { spawn, spawnSync } from 'node:child_process';
import { appendFileSync, cpSync, existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = dirname(fileURLToPath(import.meta.url));
const extensionRoot = resolve(here, '..', '..');
const repoRoot = resolve(extensionRoot, '..', '..');
const out = join(extensionRoot, 'build', 'e2e');
mkdirSync(out, { recursive: true });

const installed = '/tmp/code-server/node_modules/.bin/code-server'; // install-code-server.sh's default
const onPath = spawnSync('sh', ['-c', 'command -v code-server'], { encoding: 'utf8' }).stdout?.trim();
const codeServer = process.env.CODE_SERVER || onPath || (existsSync(installed) ? installed : 'code-server');
const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
const vsix = resolve(process.env.MIRON_VSIX || join(extensionRoot, 'build', 'miron-vscode.vsix'));
const serverCommand = process.env.MIRON_SERVER
    ? (process.env.MIRON_SERVER.trim().startsWith('[') ? JSON.parse(process.env.MIRON_SERVER) : process.env.MIRON_SERVER)
    : [process.execPath, join(extensionRoot, 'test', 'fake-miron.mjs')];
const fake = !process.env.MIRON_SERVER;
// The real server finds nothing wrong in the example: the test appends a rule naming an unknown
// property to the workspace's copy, and expects its name in the Problems view.
const expectedDiagnostic = process.env.MIRON_DIAGNOSTIC || (fake ? 'fake-miron: intralogistics.miron checked' : 'nonexistent');

const results = [];
async function check(name, fn) {
    const started = Date.now();
    try {
        await fn();
        results.push({ name, time: (Date.now() - started) / 1000 });
        console.log(`✔ ${name}`);
    } catch (err) {
        results.push({ name, time: (Date.now() - started) / 1000, error: err });
        console.log(`✖ ${name}\n  ${String(err?.stack ?? err).split('\n').join('\n  ')}`);
    }
}

function freePort() {
    return new Promise((res, rej) => {
        const s = createServer();
        s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => res(port)); });
        s.on('error', rej);
    });
}

async function waitForHttp(url, ms) {
    const end = Date.now() + ms;
    for (;;) {
        try {
            const r = await fetch(url);
            if (r.ok) return;
        } catch { /* not yet */ }
        if (Date.now() > end) throw new Error(`${url} did not answer within ${ms} ms`);
        await new Promise((r) => setTimeout(r, 250));
    }
}

function writeJunit() {
    const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
    const failures = results.filter((r) => r.error).length;
    const lines = ['<?xml version="1.0" encoding="UTF-8"?>',
        `<testsuite name="vscode-e2e" tests="${results.length}" skipped="0" failures="${failures}" errors="0" ` +
        `timestamp="${new Date().toISOString().replace(/\.\d+Z$/, '')}" hostname="localhost" time="0">`];
    for (const r of results) {
        const head = `  <testcase name="${esc(r.name)}" classname="vscode.e2e.code-server" time="${r.time.toFixed(3)}"`;
        lines.push(r.error
            ? `${head}>\n    <failure message="${esc(r.error.message ?? r.error)}">${esc(r.error.stack ?? r.error)}</failure>\n  </testcase>`
            : `${head}/>`);
    }
    lines.push('</testsuite>', '');
    const target = resolve(extensionRoot, process.env.MIRON_JUNIT_XML || '../build/test-results/test/TEST-vscode-e2e.xml');
    mkdirSync(dirname(target), { recursive: true });
    writeFileSync(target, lines.join('\n'));
}

// ---------------------------------------------------------------- set up

if (!existsSync(vsix)) {
    console.error(`no ${vsix}: run npm run package first`);
    process.exit(2);
}
const scratch = mkdtempSync(join(tmpdir(), 'miron-e2e-'));
const workspace = join(scratch, 'intralogistics');
cpSync(join(repoRoot, 'examples', 'intralogistics'), workspace, { recursive: true });
mkdirSync(join(workspace, '.vscode'));
// A woven tree: .ext.xml must open as a BT, not as plain XML.
cpSync(join(workspace, 'intralogistics.bt'), join(workspace, 'woven.ext.xml'));
if (!fake) {
    appendFileSync(join(workspace, 'intralogistics.miron'), '\nrule broken : roqme.nonexistent < 0.5\n  implies task = task::dock\n');
}
writeFileSync(join(workspace, '.vscode', 'settings.json'), JSON.stringify({
    'miron.server.command': serverCommand,
    'miron.trace.server': 'messages',
    'miron.server.env': { FAKE_MIRON_LOG: join(out, 'fake-miron.log') },
}, null, 2));
const userData = join(scratch, 'user');
const extensions = join(scratch, 'extensions');
mkdirSync(join(userData, 'User'), { recursive: true });
mkdirSync(extensions, { recursive: true });
writeFileSync(join(userData, 'User', 'settings.json'), JSON.stringify({
    'workbench.startupEditor': 'none',
    'workbench.tips.enabled': false,
    'workbench.enableExperiments': false,
    'security.workspace.trust.enabled': false,
    'extensions.autoCheckUpdates': false,
    'extensions.autoUpdate': false,
    'extensions.ignoreRecommendations': true,
    'update.mode': 'none',
    'telemetry.telemetryLevel': 'off',
    'chat.disableAIFeatures': true,
    'window.commandCenter': false,
}, null, 2));
const config = join(scratch, 'config.yaml');
writeFileSync(config, 'auth: none\ncert: false\n');
const common = ['--config', config, '--user-data-dir', userData, '--extensions-dir', extensions];

const install = spawnSync(codeServer, [...common, '--install-extension', vsix], { encoding: 'utf8' });
if (install.error || install.status !== 0) {
    console.error(`code-server --install-extension failed: ${install.error ?? install.stderr}\n` +
        'Install code-server with test/e2e/install-code-server.sh and set CODE_SERVER.');
    process.exit(2);
}

const port = await freePort();
const log = [];
const server = spawn(codeServer, [...common, '--bind-addr', `127.0.0.1:${port}`, '--auth', 'none',
    '--disable-telemetry', '--disable-update-check', '--disable-workspace-trust', '--disable-getting-started-override',
    workspace], { stdio: ['ignore', 'pipe', 'pipe'], detached: false });
server.stdout.on('data', (d) => log.push(d.toString()));
server.stderr.on('data', (d) => log.push(d.toString()));

let browser;
try {
    await waitForHttp(`http://127.0.0.1:${port}/healthz`, 60000);
    browser = await chromium.launch({
        executablePath: chromiumPath,
        headless: true,
        args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
            '--disable-sync', '--no-first-run', '--disable-dev-shm-usage'],
    });
    const page = await browser.newPage({ viewport: { width: 1600, height: 1000 } });
    await page.goto(`http://127.0.0.1:${port}/?folder=${encodeURIComponent(workspace)}`);
    await page.locator('.monaco-workbench').waitFor({ timeout: 60000 });
    // The explorer of the opened folder.
    await page.getByRole('treeitem', { name: 'intralogistics.miron' }).waitFor({ timeout: 60000 });

    const open = async (file) => {
        await page.getByRole('treeitem', { name: file }).first().click();
        await page.locator(`.tabs-container .tab[aria-label*="${file}"]`).first().waitFor({ timeout: 30000 });
    };
    const languageMode = () => page.locator('#status\\.editor\\.mode').innerText({ timeout: 30000 });
    const expectLanguage = async (name) => {
        const end = Date.now() + 30000;
        let mode = '';
        while (Date.now() < end) {
            mode = (await languageMode()).trim();
            if (mode === name) return;
            await page.waitForTimeout(250);
        }
        throw new Error(`language mode: expected ${name}, got ${mode}`);
    };

    const runCommand = async (title) => {
        await page.keyboard.press('F1');
        await page.keyboard.type(title);
        await page.locator('.quick-input-list .monaco-list-row', { hasText: title }).first().waitFor({ timeout: 10000 });
        await page.keyboard.press('Enter');
    };

    await check('a .miron file opens in the MIRoN language', async () => {
        await open('intralogistics.miron');
        await expectLanguage('MIRoN');
        await page.screenshot({ path: join(out, 'miron.png') });
    });
    await check('the MIRoN grammar colours the editor', async () => {
        // Tokens of different scopes get different mtkN classes: a highlighted line has several.
        const line = page.locator('.monaco-editor .view-line', { hasText: '@varpoint task' }).first();
        await line.waitFor({ timeout: 10000 });
        const classes = await line.locator('span span').evaluateAll((spans) => [...new Set(spans.map((s) => s.className))]);
        if (classes.length < 3) throw new Error(`only ${classes.join(', ')} on "@varpoint task"`);
    });
    await check('a .roqme file opens in the RoQME language', async () => {
        await open('intralogistics.roqme');
        await expectLanguage('RoQME');
    });
    await check('a .bt file opens in the BT language', async () => {
        await open('intralogistics.bt');
        await expectLanguage('Behavior Tree (BehaviorTree.CPP XML)');
    });
    await check('a woven .ext.xml file opens in the BT language, not as XML', async () => {
        await open('woven.ext.xml');
        await expectLanguage('Behavior Tree (BehaviorTree.CPP XML)');
    });
    await check('the diagnostics of the language server are in the Problems view', async () => {
        await open('intralogistics.miron');
        await page.keyboard.press('Control+Shift+M');
        const problem = page.locator('.markers-panel .monaco-list-row', { hasText: expectedDiagnostic }).first();
        await problem.waitFor({ timeout: 60000 });
        await page.screenshot({ path: join(out, 'problems.png') });
    });
    if (fake) await check('the server checks .roqme and .bt files too', async () => {
        for (const file of ['intralogistics.roqme', 'intralogistics.bt']) {
            await open(file);
            const problem = page.locator('.markers-panel .monaco-list-row', { hasText: `fake-miron: ${file} checked` }).first();
            await problem.waitFor({ timeout: 30000 });
        }
    });
    if (fake) await check('files changed on disk reach the server (workspace/didChangeWatchedFiles), .xml included', async () => {
        writeFileSync(join(workspace, 'extra.xml'), '<root main_tree_to_execute="A"><BehaviorTree ID="A"><AlwaysSuccess/></BehaviorTree></root>\n');
        const problem = page.locator('.markers-panel .monaco-list-row', { hasText: 'fake-miron: extra.xml changed on disk' }).first();
        await problem.waitFor({ timeout: 30000 });
    });
    await check('MIRoN: Generate asks the server and shows its answer', async () => {
        await open('intralogistics.miron');
        await runCommand('MIRoN: Generate');
        const toast = page.locator('.notifications-toasts', { hasText: process.env.MIRON_GENERATED || 'generated' });
        await toast.first().waitFor({ timeout: 60000 });
        await page.screenshot({ path: join(out, 'generate.png') });
    });
    if (!fake) await check('fixed on disk, the model generates: the files are written', async () => {
        cpSync(join(repoRoot, 'examples', 'intralogistics', 'intralogistics.miron'), join(workspace, 'intralogistics.miron'));
        await page.locator('.markers-panel', { hasText: 'No problems have been detected' }).first().waitFor({ timeout: 60000 });
        await open('intralogistics.miron');
        await runCommand('MIRoN: Generate');
        await page.locator('.notifications-toasts', { hasText: 'Generated 4 files' }).first().waitFor({ timeout: 120000 });
        for (const ext of ['ext.xml', 'mzn', 'dzn', 'io.json']) {
            const file = join(workspace, 'generated', `intralogistics.${ext}`);
            if (!existsSync(file)) throw new Error(`${file} was not written`);
        }
        await page.screenshot({ path: join(out, 'generated.png') });
    });
    if (fake) await check('without miron.generate in the server, MIRoN: Generate runs miron generate in a terminal', async () => {
        writeFileSync(join(workspace, '.vscode', 'settings.json'), JSON.stringify({
            'miron.server.command': serverCommand,
            'miron.server.env': { FAKE_MIRON_LOG: join(out, 'fake-miron.log'), FAKE_MIRON_NO_GENERATE: '1' },
        }, null, 2));
        // The settings change offers a restart; take it.
        const restart = page.locator('.notifications-toasts .monaco-button', { hasText: 'Restart server' }).first();
        await restart.waitFor({ timeout: 30000 });
        await restart.click();
        await page.waitForTimeout(3000);
        await open('intralogistics.miron');
        await runCommand('MIRoN: Generate');
        await page.locator('.terminal-tabs-entry, .single-terminal-tab, .terminal-tab, [aria-label*="MIRoN: Generate"]',
            { hasText: 'MIRoN: Generate' }).first().waitFor({ timeout: 30000 }).catch(async () => {
            // The tab list is hidden with one terminal: the panel title names it.
            await page.locator('.part.panel', { hasText: 'MIRoN: Generate' }).first().waitFor({ timeout: 5000 });
        });
        await page.screenshot({ path: join(out, 'generate-terminal.png') });
    });
    await check('a missing server command is reported with a hint', async () => {
        writeFileSync(join(workspace, '.vscode', 'settings.json'), JSON.stringify({
            'miron.server.command': '/nonexistent/bin/miron',
        }, null, 2));
        const restart = page.locator('.notifications-toasts .monaco-button', { hasText: 'Restart server' }).first();
        await restart.waitFor({ timeout: 30000 });
        await restart.click();
        await page.locator('.notifications-toasts', { hasText: '/nonexistent/bin/miron does not exist' }).first()
            .waitFor({ timeout: 30000 });
        await page.screenshot({ path: join(out, 'missing-server.png') });
    });
} catch (err) {
    results.push({ name: 'code-server and Chromium start', time: 0, error: err });
    console.log(`✖ code-server and Chromium start\n  ${String(err?.stack ?? err)}`);
} finally {
    if (browser) {
        try {
            const [page] = browser.contexts()[0]?.pages() ?? [];
            if (page) await page.screenshot({ path: join(out, 'last.png') });
        } catch { /* best effort */ }
        await browser.close();
    }
    server.kill('SIGTERM');
    writeFileSync(join(out, 'code-server.log'), log.join(''));
    rmSync(scratch, { recursive: true, force: true });
}

writeJunit();
const failed = results.filter((r) => r.error).length;
console.log(`${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
