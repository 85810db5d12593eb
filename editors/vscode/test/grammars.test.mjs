// The TextMate grammars on the example models: known tokens get the expected scopes.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { repoRoot, tokenize, tokenizeFile } from './tokenize.mjs';

const example = (...p) => join(repoRoot, 'examples', ...p);

/**
 * The scopes of the token `text` on the first line containing `lineContains` (the `nth` such
 * token on that line, from 0).
 */
function scopes(tokens, lineContains, text, nth = 0) {
    const line = tokens.find((t) => t.lineText.includes(lineContains))?.line;
    assert.notEqual(line, undefined, `no line contains ${JSON.stringify(lineContains)}`);
    const found = tokens.filter((t) => t.line === line && t.text.trim() === text);
    assert.ok(found.length > nth, `no token ${JSON.stringify(text)} on line ${line + 1}: ` +
        JSON.stringify(tokens.filter((t) => t.line === line).map((t) => t.text)));
    return found[nth].scopes;
}

function expectScope(tokens, lineContains, text, scope, nth = 0) {
    const s = scopes(tokens, lineContains, text, nth);
    assert.ok(s.some((x) => x.split(' ').includes(scope) || x.startsWith(scope + '.')),
        `${JSON.stringify(text)} in ${JSON.stringify(lineContains)}: expected ${scope}, got ${s.join(' ')}`);
}

function expectNoScope(tokens, lineContains, text, scopePrefix, nth = 0) {
    const s = scopes(tokens, lineContains, text, nth);
    assert.ok(!s.some((x) => x.startsWith(scopePrefix)),
        `${JSON.stringify(text)} in ${JSON.stringify(lineContains)}: unexpected ${scopePrefix} in ${s.join(' ')}`);
}

describe('RoQME grammar (intralogistics.roqme)', async () => {
    const t = await tokenizeFile('roqme', example('intralogistics', 'intralogistics.roqme'));

    test('documentation comments', () => {
        expectScope(t, 'QoS metrics of a warehouse robot', '/**', 'comment.block.documentation.roqme');
        expectScope(t, 'QoS metrics of a warehouse robot', 'QoS metrics of a warehouse robot that picks, delivers and charges.',
            'comment.block.documentation.roqme');
    });
    test('header: roqme and the namespace', () => {
        expectScope(t, 'roqme Intralogistics', 'roqme', 'keyword.other.roqme.roqme');
        expectScope(t, 'roqme Intralogistics', 'Intralogistics', 'entity.name.namespace.roqme');
    });
    test('declarations: type, context, param, var, timer, property, observation', () => {
        expectScope(t, 'type AvailableSpace', 'type', 'storage.type.roqme');
        expectScope(t, 'type AvailableSpace', 'AvailableSpace', 'entity.name.type.roqme');
        expectScope(t, 'context BatteryLevel', 'context', 'storage.type.roqme');
        expectScope(t, 'context BatteryLevel', 'BatteryLevel', 'variable.other.definition.roqme');
        expectScope(t, 'param LowBattery', 'param', 'storage.type.roqme');
        expectScope(t, 'var recentDeliveries', 'var', 'storage.type.roqme');
        expectScope(t, 'timer sinceLastDelivery', 'timer', 'storage.type.roqme');
        expectScope(t, 'property safety reference', 'property', 'storage.type.roqme');
        expectScope(t, 'observation tooClose', 'observation', 'storage.type.roqme');
        expectScope(t, 'observation tooClose', 'tooClose', 'entity.name.function.observation.roqme');
    });
    test('types, options and units', () => {
        expectScope(t, 'type AvailableSpace', 'enum', 'support.type.roqme');
        expectScope(t, 'context BatteryLevel', 'number', 'support.type.roqme');
        expectScope(t, 'context Docked', 'boolean', 'support.type.roqme');
        expectScope(t, 'context DeliveryDone', 'eventtype', 'support.type.roqme');
        expectScope(t, 'context BatteryLevel', 'unit', 'keyword.other.option.roqme');
        expectScope(t, 'context BatteryLevel', '%', 'string.quoted.double.roqme');
        expectScope(t, 'param LowBattery', 'default', 'keyword.other.option.roqme');
        expectScope(t, 'property safety reference', 'reference', 'keyword.other.option.roqme');
        expectScope(t, 'property mission_completion', 'survival', 'keyword.other.option.roqme');
    });
    test('numbers and time values', () => {
        expectScope(t, 'param LowBattery', '30', 'constant.numeric.roqme');
        expectScope(t, 'context HumanNearby', '1.5', 'constant.numeric.roqme');
        expectScope(t, 'var recentDeliveries', '10', 'constant.numeric.roqme');
        expectScope(t, 'var recentDeliveries', 'minutes', 'keyword.other.unit.time.roqme');
        expectScope(t, 'property safety reference', '0.7', 'constant.numeric.roqme');
    });
    test('observations: actions, strengths, enum literals, operators', () => {
        expectScope(t, 'observation tooClose', 'undermines', 'keyword.other.action.roqme');
        expectScope(t, 'observation tooClose', 'safety', 'variable.other.property.roqme');
        expectScope(t, 'observation tooClose', 'high', 'constant.language.strength.roqme');
        expectScope(t, 'observation emergency', 'veryhigh', 'constant.language.strength.roqme');
        expectScope(t, 'observation openSpace', 'AvailableSpace', 'entity.name.type.roqme');
        expectScope(t, 'observation openSpace', '::', 'punctuation.separator.namespace.roqme');
        expectScope(t, 'observation openSpace', 'HIGH', 'variable.other.enummember.roqme');
        expectScope(t, 'observation openSpace', 'and', 'keyword.operator.logical.roqme');
        expectScope(t, 'observation openSpace', '=', 'keyword.operator.comparison.roqme');
        expectScope(t, 'observation openSpace', '>', 'keyword.operator.comparison.roqme');
        expectScope(t, 'context HumanNearby', ':=', 'keyword.operator.assignment.roqme');
        expectScope(t, 'reinforces mission_completion', 'reinforces', 'keyword.other.action.roqme');
        expectScope(t, 'starts sinceLastDelivery', 'starts', 'keyword.other.action.roqme');
    });
    test('functions, plain and postfix', () => {
        expectScope(t, 'var recentDeliveries', 'count', 'support.function.roqme');
        expectScope(t, "BatteryLevel'increasing", "'", 'punctuation.accessor.postfix.roqme');
        expectScope(t, "BatteryLevel'increasing", 'increasing', 'support.function.roqme');
    });
    test('MEDIUM is a strength only after reinforces/undermines', () => {
        expectNoScope(t, 'type AvailableSpace', 'MEDIUM', 'constant.language.strength');
    });
    test('line and block comments', async () => {
        const c = await tokenize('roqme', '// a line\ncontext x : boolean /* block */ // tail\n/*\n multi\n*/ param p : number');
        expectScope(c, '// a line', '// a line'.slice(2).trim(), 'comment.line.double-slash.roqme');
        expectScope(c, '/* block */', 'block', 'comment.block.roqme');
        expectScope(c, '/* block */', 'tail', 'comment.line.double-slash.roqme');
        expectScope(c, ' multi', 'multi', 'comment.block.roqme');
        expectScope(c, '*/ param p', 'param', 'storage.type.roqme');
        expectNoScope(c, '/* block */', 'block', 'comment.block.documentation');
    });
    test('/**/ and /***/ are plain comments, as in the language', async () => {
        const c = await tokenize('roqme', '/**/ context a : boolean\n/***/ context b : boolean\n/*** banner ***/ context d : boolean');
        expectScope(c, '/**/', 'context', 'storage.type.roqme');
        expectScope(c, '/***/', 'context', 'storage.type.roqme');
        expectNoScope(c, 'banner', '** banner **', 'comment.block.documentation');
    });
    test('strings with escapes', async () => {
        const c = await tokenize('roqme', 'context c : number unit "m\\"s"');
        expectScope(c, 'context c', '\\"', 'constant.character.escape.roqme');
    });
});

describe('MIRoN grammar (intralogistics.miron)', async () => {
    const t = await tokenizeFile('miron', example('intralogistics', 'intralogistics.miron'));

    test('imports with aliases', () => {
        expectScope(t, 'import "intralogistics.bt"', 'import', 'keyword.other.miron');
        expectScope(t, 'import "intralogistics.bt"', 'intralogistics.bt', 'string.quoted.double.miron');
        expectScope(t, 'import "intralogistics.bt"', 'as', 'keyword.other.as.miron');
        expectScope(t, 'import "intralogistics.bt"', 'main', 'entity.name.namespace.miron');
        expectScope(t, 'import "intralogistics.roqme"', 'roqme', 'entity.name.namespace.miron');
    });
    test('@varpoint declarations', () => {
        expectScope(t, '@varpoint task', '@', 'storage.type.annotation.miron');
        expectScope(t, '@varpoint task', 'varpoint', 'storage.type.annotation.miron');
        expectScope(t, '@varpoint task', 'task', 'variable.other.definition.varpoint.miron');
        expectScope(t, '@varpoint task', 'enum', 'support.type.miron');
        expectScope(t, '@varpoint maxVelocity', 'number', 'support.type.miron');
        expectScope(t, 'pickDeliverCharge : preset', 'preset', 'constant.language.preset.miron');
    });
    test('impact operators ++ after a property', () => {
        expectScope(t, '10 affects roqme.safety++', 'affects', 'keyword.other.affects.miron');
        expectScope(t, '10 affects roqme.safety++', '++', 'keyword.operator.impact.positive.miron');
        expectScope(t, '10 affects roqme.safety++', 'safety', 'variable.other.property.miron');
        expectScope(t, '10 affects roqme.safety++', 'roqme', 'entity.name.namespace.miron');
        expectNoScope(t, '10 affects roqme.safety++', 'roqme', 'keyword');
        expectScope(t, '100 affects roqme.mission_completion++', '++', 'keyword.operator.impact.positive.miron');
    });
    test('bindings: in, in arch and its settings', () => {
        expectScope(t, '} in main.PickDeliverChargeSubtree', 'in', 'keyword.other.binding.miron');
        expectScope(t, '} in main.PickDeliverChargeSubtree', 'main', 'entity.name.namespace.miron');
        expectScope(t, 'in arch {', 'arch', 'keyword.other.binding.arch.miron');
        expectScope(t, 'parameterSetRepository "CommNavigationObjects"', 'parameterSetRepository', 'variable.other.property.arch.miron');
        expectScope(t, 'parameterSetRepository "CommNavigationObjects"', 'CommNavigationObjects', 'string.quoted.double.miron');
        expectScope(t, 'parameter "transvel"', 'parameter', 'variable.other.property.arch.miron');
    });
    test('rules', () => {
        expectScope(t, 'rule noBattery', 'rule', 'storage.type.miron');
        expectScope(t, 'rule noBattery', 'noBattery', 'entity.name.function.rule.miron');
        expectScope(t, 'rule noBattery', '<', 'keyword.operator.comparison.miron');
        expectScope(t, 'rule noBattery', '0.3', 'constant.numeric.miron');
        expectScope(t, 'implies task = task::dock', 'implies', 'keyword.control.implies.miron');
        expectScope(t, 'implies task = task::dock', 'dock', 'variable.other.enummember.miron');
    });
    test('requirements', () => {
        expectScope(t, 'requirement docksOnLowBattery', 'requirement', 'storage.type.miron');
        expectScope(t, 'requirement docksOnLowBattery', 'docksOnLowBattery', 'entity.name.function.requirement.miron');
        expectScope(t, '  always (roqme.power_autonomy', 'always', 'keyword.control.temporal.miron');
        expectScope(t, '  always (roqme.power_autonomy', 'implies', 'keyword.control.implies.miron');
        expectScope(t, '  always (roqme.power_autonomy', 'eventually', 'keyword.control.temporal.miron');
        expectScope(t, '  always (roqme.power_autonomy', 'within', 'keyword.control.temporal.miron');
        expectScope(t, '  always (roqme.power_autonomy', 'seconds', 'keyword.other.unit.time.miron');
        expectScope(t, 'requirement neverStranded', 'never', 'keyword.control.temporal.miron');
        expectScope(t, 'requirement rarelyStranded', 'with', 'keyword.other.probability.miron');
        expectScope(t, 'requirement rarelyStranded', 'probability', 'keyword.other.probability.miron');
    });
    test('number ranges', () => {
        expectScope(t, '@varpoint maxVelocity', '10', 'constant.numeric.miron');
        expectScope(t, '@varpoint maxVelocity', '100', 'constant.numeric.miron');
    });
});

describe('MIRoN grammar (hospital.miron)', async () => {
    const t = await tokenizeFile('miron', example('hospital-delivery', 'hospital.miron'));

    test('all six impact intensities', () => {
        expectScope(t, 'careful : bt.NavigateCarefully', '+++', 'keyword.operator.impact.positive.miron');
        expectScope(t, 'careful : bt.NavigateCarefully', '++', 'keyword.operator.impact.positive.miron');
        expectScope(t, 'careful : bt.NavigateCarefully', '--', 'keyword.operator.impact.negative.miron');
        expectScope(t, 'elevator : bt.NavigateByElevator', '+', 'keyword.operator.impact.positive.miron');
        expectScope(t, 'elevator : bt.NavigateByElevator', '-', 'keyword.operator.impact.negative.miron');
        expectScope(t, 'charge : bt.ChargeFirst', '---', 'keyword.operator.impact.negative.miron');
        expectScope(t, 'announce : bt.AnnounceArrival', '+', 'keyword.operator.impact.positive.miron');
    });
    test('header, doc comment, before/after bindings with XPath', () => {
        expectScope(t, 'miron HospitalDelivery', 'miron', 'keyword.other.miron.miron');
        expectScope(t, 'miron HospitalDelivery', 'HospitalDelivery', 'entity.name.namespace.miron');
        expectScope(t, 'Replaces the navigation subtree', 'Replaces the navigation subtree by a careful or an elevator-based variant.',
            'comment.block.documentation.miron');
        expectScope(t, '} before bt.fetch', 'before', 'keyword.other.binding.miron');
        expectScope(t, '} after "//Action', 'after', 'keyword.other.binding.miron');
        expectScope(t, '} after "//Action', "//Action[@ID='Handover']", 'string.quoted.double.miron');
        expectScope(t, '@varpoint driveSpeed', 'm/s', 'string.quoted.double.miron');
    });
    test('logical operators and alias::Type::LITERAL', () => {
        expectScope(t, 'rule nightShift', '&', 'keyword.operator.logical.miron');
        expectScope(t, 'rule nightShift', '!', 'keyword.operator.logical.miron');
        expectScope(t, 'rule crowdedCorridor', '|', 'keyword.operator.logical.miron');
        expectScope(t, 'rule crowdedCorridor', 'Crowding', 'entity.name.type.miron');
        expectScope(t, 'rule crowdedCorridor', 'DENSE', 'variable.other.enummember.miron');
        expectScope(t, 'implies { navigation = navigation::careful', '<=', 'keyword.operator.comparison.miron');
    });
    test('arithmetic minus is not an impact', async () => {
        const c = await tokenize('miron', 'rule r : a - b > 0 - 1 implies x = x::y');
        expectScope(c, 'rule r', '-', 'keyword.operator.arithmetic.miron');
        expectNoScope(c, 'rule r', '-', 'keyword.operator.impact');
    });
});

describe('BT grammar (intralogistics.bt)', async () => {
    const t = await tokenizeFile('bt', example('intralogistics', 'intralogistics.bt'));

    test('prolog and comments', () => {
        expectScope(t, '<?xml version="1.0"?>', 'xml', 'meta.tag.preprocessor.xml.bt');
        expectScope(t, 'Intralogistics mission of the MIRoN seed', 'Intralogistics mission of the MIRoN seed (Figure 1), completed: the robot picks objects from',
            'comment.block.xml.bt');
    });
    test('BT element names by kind', () => {
        expectScope(t, '<root main_tree_to_execute', 'root', 'entity.name.tag.structure.bt');
        expectScope(t, '<BehaviorTree ID="Main">', 'BehaviorTree', 'entity.name.tag.structure.bt');
        expectScope(t, '<Sequence name="Charge">', 'Sequence', 'entity.name.tag.control.bt');
        expectScope(t, '</Sequence>', 'Sequence', 'entity.name.tag.control.bt');
        expectScope(t, '<SubTreePlus ID="PickDeliverCharge"', 'SubTreePlus', 'entity.name.tag.subtree.bt');
        expectScope(t, '<Action ID="objectdrop"', 'Action', 'entity.name.tag.leaf.bt');
        expectScope(t, '<RetryUntilSuccessful', 'RetryUntilSuccessful', 'entity.name.tag.decorator.bt');
        expectScope(t, '<Repeat num_cycles', 'Repeat', 'entity.name.tag.decorator.bt');
        expectScope(t, '<TreeNodesModel>', 'TreeNodesModel', 'entity.name.tag.structure.bt');
        expectScope(t, '<input_port name="x">', 'input_port', 'entity.name.tag.port.bt');
        expectScope(t, '<SubTree ID="GoTo">', 'SubTree', 'entity.name.tag.subtree.bt');
    });
    test('attributes, tree IDs and {blackboard} references', () => {
        expectScope(t, '<root main_tree_to_execute', 'main_tree_to_execute', 'entity.other.attribute-name.id.xml.bt');
        expectScope(t, '<root main_tree_to_execute', 'Main', 'entity.name.type.tree.bt');
        expectScope(t, '<Action ID="MoveTo" x=', 'MoveTo', 'entity.name.type.tree.bt');
        expectScope(t, '<SubTreePlus ID="GoTo" __shared_blackboard="false" x_input="-9.33"', '__shared_blackboard',
            'entity.other.attribute-name.xml.bt');
        expectScope(t, '<SubTreePlus ID="GoTo" __shared_blackboard="false" x_input="-9.33"', '-9.33', 'string.quoted.double.xml.bt');
        expectScope(t, '<Action ID="MoveTo" x=', 'x_input', 'variable.other.blackboard.bt');
        expectScope(t, '<Action ID="MoveTo" x=', 'y_input', 'variable.other.blackboard.bt');
        expectScope(t, '<Action ID="MoveTo" x=', '{', 'punctuation.definition.blackboard.begin.bt');
    });
    test('compact user nodes, single quotes, entities, CDATA', async () => {
        const c = await tokenize('bt', "<GoTo x='{a}' y=\"1 &amp; 2\"/>\n<![CDATA[ <x> ]]>");
        expectScope(c, '<GoTo', 'GoTo', 'entity.name.tag.node.bt');
        expectScope(c, '<GoTo', 'a', 'variable.other.blackboard.bt');
        expectScope(c, '<GoTo', 'amp', 'constant.character.entity.xml.bt');
        expectScope(c, '<GoTo', 'x', 'entity.other.attribute-name.xml.bt');
        expectScope(c, 'CDATA', '<x>', 'string.unquoted.cdata.xml.bt');
    });
});

describe('every model of the repository', () => {
    const roots = [join(repoRoot, 'examples'), join(repoRoot, 'org.miron.dsl', 'src', 'test', 'resources'),
        join(repoRoot, 'org.miron.bt', 'src', 'test', 'resources')];
    const files = [];
    const walk = (dir) => {
        let entries = [];
        try { entries = readdirSync(dir); } catch { return; }
        for (const e of entries) {
            const p = join(dir, e);
            if (statSync(p).isDirectory()) walk(p);
            else if (/\.(bt|roqme|miron)$/.test(e) || e.endsWith('.ext.xml')) files.push(p);
        }
    };
    roots.forEach(walk);

    test('tokenizes without invalid tokens, comments and strings closed at the end', async () => {
        assert.ok(files.length >= 6, `found only ${files.length} models`);
        for (const file of files) {
            const language = file.endsWith('.roqme') ? 'roqme' : file.endsWith('.miron') ? 'miron' : 'bt';
            const text = readFileSync(file, 'utf8');
            const tokens = await tokenize(language, text);
            const bad = tokens.find((t) => t.scopes.some((s) => s.startsWith('invalid')));
            // Invalid files (under invalid/) may legitimately contain anything.
            if (!/[\\/]invalid[\\/]/.test(file)) {
                assert.equal(bad, undefined, `${file}:${bad?.line + 1}: invalid token ${JSON.stringify(bad?.text)}`);
            }
        }
    });
});
