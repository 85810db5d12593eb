// package.json, language configurations and grammars are consistent; the generated grammars are
// up to date; the pure helpers of the extension behave.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { extensionRoot, manifest } from './tokenize.mjs';
import { grammars, render } from '../syntaxes/generate.mjs';

const require = createRequire(import.meta.url);
const c = manifest.contributes;

describe('package.json', () => {
    test('the three languages with their extensions (.xml is not claimed)', () => {
        const byId = Object.fromEntries(c.languages.map((l) => [l.id, l]));
        assert.deepEqual(Object.keys(byId).sort(), ['bt', 'miron', 'roqme']);
        assert.deepEqual(byId.bt.extensions, ['.bt', '.ext.xml']);
        assert.deepEqual(byId.roqme.extensions, ['.roqme']);
        assert.deepEqual(byId.miron.extensions, ['.miron']);
        for (const l of c.languages) {
            assert.ok(!l.extensions.includes('.xml'), `${l.id} claims every .xml file`);
            const config = JSON.parse(readFileSync(join(extensionRoot, l.configuration), 'utf8'));
            assert.ok(config.brackets.length > 0 && config.comments, `${l.configuration}: brackets and comments`);
        }
    });
    test('grammars exist and declare their scope names', () => {
        for (const g of c.grammars) {
            const file = join(extensionRoot, g.path);
            assert.ok(existsSync(file), file);
            assert.equal(JSON.parse(readFileSync(file, 'utf8')).scopeName, g.scopeName);
        }
    });
    test('MIRoN: Generate, the menus and the server settings', () => {
        const commands = c.commands.map((x) => x.command);
        assert.ok(commands.includes('miron.generate'));
        assert.equal(c.commands.find((x) => x.command === 'miron.generate').title, 'Generate');
        assert.equal(c.commands.find((x) => x.command === 'miron.generate').category, 'MIRoN');
        for (const [menu, items] of Object.entries(c.menus)) {
            for (const item of items) assert.ok(commands.includes(item.command), `${menu}: ${item.command}`);
        }
        assert.ok(c.menus['editor/title'].some((m) => m.command === 'miron.generate' && /miron/.test(m.when)));
        const props = c.configuration.properties;
        assert.equal(props['miron.server.command'].default, 'miron');
        // A plain string, so that the Settings UI shows a text field (issue 23, item 14).
        assert.equal(props['miron.server.command'].type, 'string');
        assert.equal(props['miron.server.args'].type, 'array');
        assert.deepEqual(props['miron.server.args'].default, []);
        assert.equal(props['miron.bt.detectXml'].default, true);
        for (const l of ['bt', 'roqme', 'miron', 'xml']) {
            assert.ok(manifest.activationEvents.includes(`onLanguage:${l}`), `activation on ${l}`);
        }
    });
    test('Generate and Convert in the command palette, for the right editors', () => {
        const palette = Object.fromEntries(c.menus.commandPalette.map((m) => [m.command, m.when]));
        assert.match(palette['miron.generate'], /editorLangId == miron/);
        for (const v of ['3', '4']) {
            const command = c.commands.find((x) => x.command === `miron.convertTo${v}`);
            assert.equal(command.title, `Convert to BehaviorTree.CPP ${v}`);
            assert.equal(command.category, 'MIRoN');
            assert.equal(palette[`miron.convertTo${v}`], 'editorLangId == bt');
        }
    });
    test('icon, repository, a description that names both BehaviorTree.CPP versions', () => {
        const icon = readFileSync(join(extensionRoot, manifest.icon));
        assert.equal(icon.subarray(1, 4).toString('ascii'), 'PNG', 'the icon is a PNG (vsce refuses SVG)');
        assert.equal(icon.readUInt32BE(16), 128, 'width 128');
        assert.equal(icon.readUInt32BE(20), 128, 'height 128');
        assert.match(manifest.repository.url, /^https:\/\//);
        assert.equal(manifest.repository.directory, 'editors/vscode');
        assert.match(manifest.description, /BehaviorTree\.CPP 3 and 4/);
        assert.doesNotMatch(manifest.scripts.package, /allow-missing-repository/);
    });
    test('snippets: tree, varpoint, rule and observation, each with a prefix, a body and a description', () => {
        const prefixes = {};
        for (const s of c.snippets) {
            assert.ok(['bt', 'roqme', 'miron'].includes(s.language), s.language);
            const snippets = JSON.parse(readFileSync(join(extensionRoot, s.path), 'utf8'));
            for (const [name, snippet] of Object.entries(snippets)) {
                assert.ok(snippet.prefix && snippet.body && snippet.description, `${s.path}: ${name}`);
                const body = [snippet.body].flat().join('\n');
                // Tab stops $1..$n without gaps, and a final $0.
                const stops = [...new Set([...body.matchAll(/\$\{?(\d+)/g)].map((m) => Number(m[1])))].sort((a, b) => a - b);
                assert.deepEqual(stops, stops.map((_, i) => i), `${s.path}: ${name}: tab stops ${stops}`);
                (prefixes[s.language] ??= []).push(...[snippet.prefix].flat());
            }
        }
        assert.ok(prefixes.bt.includes('tree'));
        for (const p of ['varpoint', 'rule', 'observation']) assert.ok(prefixes.miron.includes(p), `miron: ${p}`);
        assert.ok(prefixes.roqme.includes('observation'));
    });
    test('semantic highlighting on in the three languages', () => {
        for (const l of ['bt', 'roqme', 'miron']) {
            assert.equal(c.configurationDefaults[`[${l}]`]['editor.semanticHighlighting.enabled'], true, l);
        }
    });
    test('vsce essentials: publisher, engine, main, license, pinned vsce', () => {
        assert.ok(manifest.publisher && manifest.engines.vscode && manifest.main);
        assert.equal(manifest.license, 'EPL-2.0');
        assert.ok(existsSync(join(extensionRoot, 'LICENSE')), 'LICENSE');
        assert.ok(manifest.devDependencies['@vscode/vsce'], '@vscode/vsce is a devDependency');
        assert.ok(manifest.dependencies['vscode-languageclient']);
    });
    test('generated grammars are up to date (node syntaxes/generate.mjs)', () => {
        for (const [file, grammar] of Object.entries(grammars)) {
            assert.equal(readFileSync(join(extensionRoot, 'syntaxes', file), 'utf8'), render(grammar),
                `${file} is out of date: run node syntaxes/generate.mjs`);
        }
    });
});

describe('behaviour trees by content (out/detect.js)', () => {
    const { isBehaviorTreeXml, mayBeBehaviorTree } = require('../out/detect.js');
    test('<root> with <BehaviorTree> is a BT, in both versions and from Groot', () => {
        const tree = readFileSync(join(extensionRoot, '..', '..', 'examples', 'intralogistics', 'intralogistics.bt'), 'utf8');
        assert.ok(isBehaviorTreeXml(tree));
        assert.ok(isBehaviorTreeXml('<?xml version="1.0"?>\n<root BTCPP_format="4">\n<BehaviorTree ID="A"><AlwaysSuccess/></BehaviorTree></root>'));
        assert.ok(isBehaviorTreeXml('<root main_tree_to_execute="A"><TreeNodesModel/><BehaviorTree\n ID="A"/></root>'));
    });
    test('other XML is not', () => {
        assert.ok(!isBehaviorTreeXml('<?xml version="1.0"?><project><modelVersion>4.0.0</modelVersion></project>'));
        assert.ok(!isBehaviorTreeXml('<root><item/></root>'), 'a <root> alone');
        assert.ok(!isBehaviorTreeXml('<rootfs><BehaviorTreeX/></rootfs>'), 'longer names');
        assert.ok(!isBehaviorTreeXml('<config><!-- <root><BehaviorTree ID="x"/></root> --></config>'), 'in a comment');
        assert.ok(!isBehaviorTreeXml(''));
    });
    test('only .xml files of the XML language are looked at', () => {
        assert.ok(mayBeBehaviorTree('xml', '/w/trees/main.xml'));
        assert.ok(mayBeBehaviorTree('xml', '/w/trees/MAIN.XML'));
        assert.ok(!mayBeBehaviorTree('bt', '/w/trees/main.xml'));
        assert.ok(!mayBeBehaviorTree('xml', '/w/pom.xsd'));
        assert.ok(!mayBeBehaviorTree('plaintext', '/w/a.xml'));
    });
});

describe('launch helpers (out/launch.js)', () => {
    const { serverLaunch, describeResult, splitCommandLine } = require('../out/launch.js');

    test('miron.server.command: default, ./miron, arrays, args, ~', () => {
        assert.deepEqual(serverLaunch('miron', [], '/ws'), { command: 'miron', args: ['lsp'], cwd: '/ws' });
        assert.deepEqual(serverLaunch(undefined, undefined, undefined), { command: 'miron', args: ['lsp'], cwd: undefined });
        assert.equal(serverLaunch('./miron', [], '/ws').command, '/ws/miron');
        assert.equal(serverLaunch('/opt/miron/bin/miron', [], '/ws').command, '/opt/miron/bin/miron');
        assert.deepEqual(serverLaunch(['java', '-jar', 'miron.jar'], ['--verbose'], '/ws'),
            { command: 'java', args: ['-jar', 'miron.jar', '--verbose', 'lsp'], cwd: '/ws' });
        assert.equal(serverLaunch('~/bin/miron', [], '/ws', '/home/u').command, '/home/u/bin/miron');
        assert.equal(serverLaunch(['', ' '], [], '/ws').command, 'miron');
        assert.deepEqual(serverLaunch('java -jar "/opt/my miron/miron.jar"', ['-v'], '/ws', '/h', () => false),
            { command: 'java', args: ['-jar', '/opt/my miron/miron.jar', '-v', 'lsp'], cwd: '/ws' });
        assert.deepEqual(serverLaunch('./my tools/miron', [], '/ws', '/h', (f) => f === '/ws/my tools/miron'),
            { command: '/ws/my tools/miron', args: ['lsp'], cwd: '/ws' });
        assert.deepEqual(splitCommandLine(`a 'b c' "d \\"e\\"" f\\ g`), ['a', 'b c', 'd "e"', 'f g']);
    });
    test('the answer of miron.generate becomes a message', () => {
        // miron lsp's answer (docs/lsp.md): the server shows the message itself.
        assert.deepEqual(describeResult({ ok: true, message: 'Generated 4 files into /w/generated: a.ext.xml', written: ['/w/generated/a.ext.xml'], errors: [] }),
            { message: 'Generated 4 files into /w/generated: a.ext.xml', ok: true, shownByServer: true, errors: [], written: ['/w/generated/a.ext.xml'] });
        assert.deepEqual(describeResult({ ok: false, message: 'Not generated: a.miron has 1 error', written: [], errors: ['a.miron:1:2: x'] }),
            { message: 'Not generated: a.miron has 1 error', ok: false, shownByServer: true, errors: ['a.miron:1:2: x'], written: [] });
        // Other answers are shown by the extension.
        assert.deepEqual(describeResult('Wrote out/a.ext.xml'), { message: 'Wrote out/a.ext.xml', ok: true, shownByServer: false, errors: [], written: [] });
        assert.equal(describeResult('error: 2 problems').ok, false);
        assert.equal(describeResult({ written: ['/a/b.mzn', '/a/b.dzn'] }).message, 'MIRoN: Generate done. Wrote b.mzn, b.dzn.');
        assert.equal(describeResult({ errors: ['f:1:1: e'] }).message, 'MIRoN: Generate failed. f:1:1: e');
        assert.equal(describeResult({ success: false }).ok, false);
        assert.equal(describeResult(null).ok, true);
    });
});
