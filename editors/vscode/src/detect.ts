// Pure helpers (no `vscode` import): which documents are behaviour trees by their content.

/** How much of a file is read to decide: a BT's `<root>` and first `<BehaviorTree>` come early. */
export const SNIFF_LENGTH = 64 * 1024;

/**
 * Whether `text` is BehaviorTree.CPP XML: a `<root` element with a `<BehaviorTree` element
 * (BehaviorTree.CPP 3 and 4, Groot's files). Comments are skipped, so a `<root>` mentioned in an
 * XML comment of another kind of file does not count.
 */
export function isBehaviorTreeXml(text: string): boolean {
    const head = text.slice(0, SNIFF_LENGTH).replace(/<!--[\s\S]*?(-->|$)/g, '');
    return /<root[\s>/]/.test(head) && /<BehaviorTree[\s>/]/.test(head);
}

/** Whether a document of language `languageId` at `path` is one whose content is checked. */
export function mayBeBehaviorTree(languageId: string, path: string): boolean {
    return languageId === 'xml' && /\.xml$/i.test(path);
}
