// node:test reporter writing JUnit XML in the form Gradle writes it (one <testsuite> with
// tests/skipped/failures/errors in that order), so ./run-tests counts these tests with the Java
// ones. The file goes to $MIRON_JUNIT_XML, by default ../build/test-results/test/TEST-vscode.xml
// (editors/build/..., which run-tests' glob ./*/build/test-results/test/TEST-*.xml finds).
// It prints nothing itself: use it next to the spec reporter.
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';

const escape = (s) => String(s)
    .replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;')
    // eslint-disable-next-line no-control-regex
    .replace(/[\u0000-\u0008\u000b\u000c\u000e-\u001f]/g, '');

export default async function* junitReporter(source) {
    const cases = [];
    const fileFailures = [];
    const start = Date.now();
    for await (const event of source) {
        if (event.type !== 'test:pass' && event.type !== 'test:fail') continue;
        const data = event.data;
        // Suites (describe) and files report too: count only leaf tests.
        if (data.details?.type === 'suite') continue;
        // A test file itself: counted only when it fails without a failing test (it did not load).
        if (data.nesting === 0 && data.name === data.file) {
            if (event.type === 'test:fail') fileFailures.push(event);
            continue;
        }
        const classname = (data.file ?? 'vscode').replace(/^.*[\\/]/, '').replace(/\.[cm]?js$/, '');
        cases.push({
            name: data.name,
            classname: `vscode.${classname}`,
            time: (data.details?.duration_ms ?? 0) / 1000,
            skipped: Boolean(data.skip || data.todo),
            error: event.type === 'test:fail' ? data.details?.error : undefined,
        });
    }
    for (const event of fileFailures) {
        const data = event.data;
        const classname = `vscode.${data.file.replace(/^.*[\\/]/, '').replace(/\.[cm]?js$/, '')}`;
        if (!cases.some((c) => c.error && c.classname === classname)) {
            cases.push({ name: `${classname} (the file)`, classname, time: 0, skipped: false, error: data.details?.error ?? 'failed' });
        }
    }
    const failures = cases.filter((c) => c.error).length;
    const skipped = cases.filter((c) => c.skipped && !c.error).length;
    const lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        `<testsuite name="vscode" tests="${cases.length}" skipped="${skipped}" failures="${failures}" errors="0" ` +
            `timestamp="${new Date(start).toISOString().replace(/\.\d+Z$/, '')}" hostname="localhost" ` +
            `time="${((Date.now() - start) / 1000).toFixed(3)}">`,
    ];
    for (const c of cases) {
        const head = `  <testcase name="${escape(c.name)}" classname="${escape(c.classname)}" time="${c.time.toFixed(3)}"`;
        if (c.error) {
            const err = c.error.cause ?? c.error;
            lines.push(`${head}>`,
                `    <failure message="${escape(err?.message ?? err)}" type="${escape(err?.name ?? 'Error')}">${escape(err?.stack ?? err)}</failure>`,
                '  </testcase>');
        } else if (c.skipped) {
            lines.push(`${head}>`, '    <skipped/>', '  </testcase>');
        } else {
            lines.push(`${head}/>`);
        }
    }
    lines.push('</testsuite>', '');
    const target = resolve(process.env.MIRON_JUNIT_XML ?? '../build/test-results/test/TEST-vscode.xml');
    mkdirSync(dirname(target), { recursive: true });
    writeFileSync(target, lines.join('\n'));
}
