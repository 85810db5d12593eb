// Writes the TextMate grammars of RoQME and MIRoN (syntaxes/*.tmLanguage.json) from one
// description, so MIRoN (which extends RoQME) stays in step with it. Keywords follow
// org.miron.dsl/src/main/java/org/miron/dsl/Roqme.xtext and Miron.xtext.
//
//   node syntaxes/generate.mjs          rewrite the grammars
//   node syntaxes/generate.mjs --check  exit 1 when a committed grammar is out of date
//
// The BT grammar (bt.tmLanguage.json) is written by hand.
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ID = String.raw`\^?[A-Za-z_][A-Za-z0-9_]*`;
// A keyword, unless used as a name: roqme.safety (an import alias), task::dock (an owner).
const words = (list) => `\\b(?:${list.join('|')})\\b(?!\\.[A-Za-z_^]|\\s*::)`;

const ROQME = {
    // Declarations (each is followed by the declared name).
    declarations: ['context', 'param', 'var', 'timer', 'beliefvar', 'property', 'observation', 'type'],
    types: ['boolean', 'eventtype', 'time', 'enum', 'number'],
    options: ['unit', 'lower', 'upper', 'precision', 'offset', 'onetime', 'paused', 'reference', 'survival', 'default'],
    actions: ['reinforces', 'undermines', 'clears', 'sets', 'starts', 'stops', 'resumes'],
    patterns: ['once', 'while', 'repeat', 'range'],
    logical: ['not', 'and', 'or'],
    strengths: ['veryhigh', 'high', 'low', 'verylow'], // MEDIUM only after reinforces/undermines
    constants: ['true', 'false', 'event'],
    timeUnits: ['milliseconds', 'millisecond', 'seconds', 'second', 'minutes', 'minute', 'hours', 'hour', 'days', 'day'],
    functions: ['pow', 'sqrt', 'exp', 'abs', 'avg', 'min', 'max', 'count', 'sum', 'decreasing', 'increasing',
        'stable', 'eventWhen', 'update', 'period', 'first', 'last', 'at', 'size', 'isEmpty', 'includes', 'schedule'],
};

const MIRON = {
    bindings: ['in', 'before', 'after'],
    arch: ['parameterSetRepository', 'parameterSet', 'component', 'parameter'],
};

/** The repository shared by both languages; `s` is the scope suffix (roqme or miron). */
function common(s) {
    return {
        comments: {
            patterns: [
                {
                    name: `comment.block.documentation.${s}`,
                    begin: String.raw`/\*\*(?![*/])`,
                    end: String.raw`\*/`,
                    beginCaptures: { 0: { name: `punctuation.definition.comment.begin.${s}` } },
                    endCaptures: { 0: { name: `punctuation.definition.comment.end.${s}` } },
                },
                {
                    name: `comment.block.${s}`,
                    begin: String.raw`/\*`,
                    end: String.raw`\*/`,
                    beginCaptures: { 0: { name: `punctuation.definition.comment.begin.${s}` } },
                    endCaptures: { 0: { name: `punctuation.definition.comment.end.${s}` } },
                },
                {
                    name: `comment.line.double-slash.${s}`,
                    begin: '//',
                    end: '$',
                    beginCaptures: { 0: { name: `punctuation.definition.comment.${s}` } },
                },
            ],
        },
        strings: {
            name: `string.quoted.double.${s}`,
            begin: '"',
            end: '"',
            beginCaptures: { 0: { name: `punctuation.definition.string.begin.${s}` } },
            endCaptures: { 0: { name: `punctuation.definition.string.end.${s}` } },
            patterns: [{ name: `constant.character.escape.${s}`, match: String.raw`\\.` }],
        },
        numbers: {
            patterns: [
                {
                    // 10 minutes, 1.5 seconds: a time value.
                    match: String.raw`(?<![\w.])(\d+(?:\.\d+(?:[eE][+-]?\d+)?)?)\s+(${ROQME.timeUnits.join('|')})\b`,
                    captures: {
                        1: { name: `constant.numeric.${s}` },
                        2: { name: `keyword.other.unit.time.${s}` },
                    },
                },
                {
                    name: `constant.numeric.${s}`,
                    match: String.raw`(?<![\w.])\d+(?:\.\d+(?:[eE][+-]?\d+)?)?\b`,
                },
            ],
        },
        units: {
            // unit "m/s" or unit m: the unit name of a number type.
            match: String.raw`\b(unit)\s+(${ID})\b`,
            captures: {
                1: { name: `keyword.other.option.${s}` },
                2: { name: `keyword.other.unit.${s}` },
            },
        },
        'enum-literals': {
            patterns: [
                {
                    // Owner::LITERAL, alias::Type::LITERAL: the owners...
                    match: String.raw`(${ID})\s*(::)`,
                    captures: {
                        1: { name: `entity.name.type.${s}` },
                        2: { name: `punctuation.separator.namespace.${s}` },
                    },
                },
                {
                    // ...and the literal itself.
                    match: String.raw`(?<=::)\s*(${ID})\b(?!\s*::)`,
                    captures: { 1: { name: `variable.other.enummember.${s}` } },
                },
            ],
        },
        functions: {
            patterns: [
                {
                    // x'avg(30 seconds), x'avg
                    match: String.raw`(')\s*(${ROQME.functions.join('|')})\b`,
                    captures: {
                        1: { name: `punctuation.accessor.postfix.${s}` },
                        2: { name: `support.function.${s}` },
                    },
                },
                {
                    match: String.raw`\b(${ROQME.functions.join('|')})\s*(?=\()`,
                    captures: { 1: { name: `support.function.${s}` } },
                },
                {
                    // belief, belief(safety)
                    name: `variable.language.belief.${s}`,
                    match: String.raw`\bbelief\b`,
                },
            ],
        },
        actions: {
            patterns: [
                {
                    // reinforces safety high, undermines roqme.safety MEDIUM
                    match: String.raw`\b(reinforces|undermines)\s+((?:${ID}\.)*${ID})(?:\s+(veryhigh|high|MEDIUM|low|verylow)\b)?`,
                    captures: {
                        1: { name: `keyword.other.action.${s}` },
                        2: { name: `variable.other.property.${s}` },
                        3: { name: `constant.language.strength.${s}` },
                    },
                },
                { name: `keyword.other.action.${s}`, match: words(ROQME.actions) },
                { name: `constant.language.strength.${s}`, match: words(ROQME.strengths) },
            ],
        },
        'roqme-keywords': {
            patterns: [
                // roqme Name: RoQME's header (MIRoN's is miron Name; there roqme is just a name).
                ...(s === 'roqme' ? [{
                    match: String.raw`\b(roqme)\s+((?:${ID}\.)*${ID})`,
                    captures: {
                        1: { name: `keyword.other.roqme.${s}` },
                        2: { name: `entity.name.namespace.${s}` },
                    },
                }] : []),
                {
                    // type T, observation o, context c ...
                    match: String.raw`\b(type)\s+(${ID})`,
                    captures: {
                        1: { name: `storage.type.${s}` },
                        2: { name: `entity.name.type.${s}` },
                    },
                },
                {
                    match: String.raw`\b(observation)\s+(${ID})`,
                    captures: {
                        1: { name: `storage.type.${s}` },
                        2: { name: `entity.name.function.observation.${s}` },
                    },
                },
                {
                    match: String.raw`\b(context|param|var|timer|beliefvar|property)\s+(${ID})`,
                    captures: {
                        1: { name: `storage.type.${s}` },
                        2: { name: `variable.other.definition.${s}` },
                    },
                },
                { name: `storage.type.${s}`, match: words(ROQME.declarations) },
                { name: `keyword.other.${s}`, match: words(s === 'roqme' ? ['roqme', 'import'] : ['import']) },
                { name: `support.type.${s}`, match: words(ROQME.types) },
                { name: `keyword.other.option.${s}`, match: words(ROQME.options) },
                { name: `keyword.control.pattern.${s}`, match: words(ROQME.patterns) },
                { name: `keyword.operator.logical.${s}`, match: words(ROQME.logical) },
                { name: `constant.language.${s}`, match: words(ROQME.constants) },
            ],
        },
        operators: {
            patterns: [
                { name: `keyword.operator.assignment.${s}`, match: ':=' },
                { name: `keyword.operator.followed-by.${s}`, match: '->' },
                { name: `keyword.operator.comparison.${s}`, match: '!=|<=|>=|=|<|>' },
                { name: `keyword.operator.logical.${s}`, match: String.raw`!|&|\|` },
                { name: `keyword.operator.ternary.${s}`, match: String.raw`\?` },
                { name: `keyword.operator.arithmetic.${s}`, match: String.raw`\+|-|\*|/` },
                { name: `punctuation.separator.colon.${s}`, match: ':' },
                { name: `punctuation.separator.comma.${s}`, match: ',' },
            ],
        },
        'qualified-names': {
            // alias.name: the alias (or namespace) part.
            match: String.raw`(${ID})(\.)(?=\^?[A-Za-z_])`,
            captures: {
                1: { name: `entity.name.namespace.${s}` },
                2: { name: `punctuation.accessor.${s}` },
            },
        },
        brackets: {
            patterns: [
                { name: `punctuation.section.block.begin.${s}`, match: String.raw`\{` },
                { name: `punctuation.section.block.end.${s}`, match: String.raw`\}` },
                { name: `punctuation.section.parens.begin.${s}`, match: String.raw`\(` },
                { name: `punctuation.section.parens.end.${s}`, match: String.raw`\)` },
                { name: `punctuation.section.brackets.begin.${s}`, match: String.raw`\[` },
                { name: `punctuation.section.brackets.end.${s}`, match: String.raw`\]` },
            ],
        },
    };
}

const COMMON_ORDER = ['comments', 'strings', 'units', 'numbers', 'enum-literals', 'functions', 'actions',
    'roqme-keywords', 'qualified-names', 'operators', 'brackets'];

function roqme() {
    const repository = common('roqme');
    return {
        $schema: 'https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json',
        name: 'RoQME',
        scopeName: 'source.roqme',
        fileTypes: ['roqme'],
        patterns: COMMON_ORDER.map((k) => ({ include: `#${k}` })),
        repository,
    };
}

function miron() {
    const s = 'miron';
    const repository = {
        ...common(s),
        'miron-keywords': {
            patterns: [
                {
                    // miron Name
                    match: String.raw`\b(miron)\s+((?:${ID}\.)*${ID})`,
                    captures: {
                        1: { name: `keyword.other.miron.${s}` },
                        2: { name: `entity.name.namespace.${s}` },
                    },
                },
                {
                    // import "x.bt" as main
                    match: String.raw`\b(as)\s+(${ID})`,
                    captures: {
                        1: { name: `keyword.other.as.${s}` },
                        2: { name: `entity.name.namespace.${s}` },
                    },
                },
                {
                    // @varpoint name, varpoint name
                    match: String.raw`(@)?\b(varpoint)\s+(${ID})`,
                    captures: {
                        1: { name: `storage.type.annotation.${s} punctuation.definition.annotation.${s}` },
                        2: { name: `storage.type.annotation.${s}` },
                        3: { name: `variable.other.definition.varpoint.${s}` },
                    },
                },
                {
                    match: String.raw`\b(rule)\s+(${ID})`,
                    captures: {
                        1: { name: `storage.type.${s}` },
                        2: { name: `entity.name.function.rule.${s}` },
                    },
                },
                {
                    match: String.raw`\b(requirement)\s+(${ID})(?=\s*:)`,
                    captures: {
                        1: { name: `storage.type.${s}` },
                        2: { name: `entity.name.function.requirement.${s}` },
                    },
                },
                {
                    // requirements: ... with probability >= 0.9 (with and probability are names elsewhere)
                    match: String.raw`\b(with)\s+(probability)\b`,
                    captures: {
                        1: { name: `keyword.other.probability.${s}` },
                        2: { name: `keyword.other.probability.${s}` },
                    },
                },
                {
                    match: String.raw`(@)?\b(varpoint)\b`,
                    captures: {
                        1: { name: `storage.type.annotation.${s} punctuation.definition.annotation.${s}` },
                        2: { name: `storage.type.annotation.${s}` },
                    },
                },
                { name: `storage.type.${s}`, match: words(['rule']) },
                { name: `keyword.other.${s}`, match: words(['miron', 'as']) },
                { name: `keyword.control.implies.${s}`, match: words(['implies']) },
                { name: `keyword.control.temporal.${s}`, match: words(['always', 'never', 'eventually']) },
                // within 5 seconds (within is a name elsewhere)
                { name: `keyword.control.temporal.${s}`, match: String.raw`\bwithin\b(?=\s*[0-9])` },
                { name: `keyword.other.affects.${s}`, match: words(['affects']) },
                { name: `constant.language.preset.${s}`, match: words(['preset']) },
                {
                    // in arch { ... }
                    match: String.raw`\b(in)\s+(arch)\b`,
                    captures: {
                        1: { name: `keyword.other.binding.${s}` },
                        2: { name: `keyword.other.binding.arch.${s}` },
                    },
                },
                { name: `keyword.other.binding.${s}`, match: words(MIRON.bindings) },
                {
                    // The settings of an architecture binding, each followed by its string.
                    match: String.raw`\b(${MIRON.arch.join('|')})\b(?=\s*")`,
                    captures: { 1: { name: `variable.other.property.arch.${s}` } },
                },
            ],
        },
        impacts: {
            // roqme.safety++, qos.timeliness---: a quality impact, the intensity right after the
            // property and followed by a comma, a closing brace or the end of the line.
            match: String.raw`((?:${ID}\.)*${ID})\s*(?:(\+\+\+|\+\+|\+)|(---|--|-))(?=\s*(?:,|\}|//|/\*|$))`,
            captures: {
                1: {
                    patterns: [{ include: '#qualified-names' }],
                    name: `variable.other.property.${s}`,
                },
                2: { name: `keyword.operator.impact.positive.${s}` },
                3: { name: `keyword.operator.impact.negative.${s}` },
            },
        },
    };
    const order = [...COMMON_ORDER];
    // MIRoN's own rules take precedence over RoQME's at the same position.
    order.splice(order.indexOf('enum-literals'), 0, 'impacts', 'miron-keywords');
    return {
        $schema: 'https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json',
        name: 'MIRoN',
        scopeName: 'source.miron',
        fileTypes: ['miron'],
        patterns: order.map((k) => ({ include: `#${k}` })),
        repository,
    };
}

export const grammars = {
    'roqme.tmLanguage.json': roqme(),
    'miron.tmLanguage.json': miron(),
};

export function render(grammar) {
    return JSON.stringify(grammar, null, 2) + '\n';
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
    const here = dirname(fileURLToPath(import.meta.url));
    const check = process.argv.includes('--check');
    let stale = 0;
    for (const [file, grammar] of Object.entries(grammars)) {
        const target = join(here, file);
        const text = render(grammar);
        if (check) {
            let current = '';
            try { current = readFileSync(target, 'utf8'); } catch { /* missing */ }
            if (current !== text) {
                console.error(`${file} is out of date: run node syntaxes/generate.mjs`);
                stale++;
            }
        } else {
            writeFileSync(target, text);
            console.log(`wrote ${file}`);
        }
    }
    process.exit(stale ? 1 : 0);
}
