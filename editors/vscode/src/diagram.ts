// "MIRoN: Show Diagram": the tree of the active editor in a webview beside it, drawn by Sprotty
// from the models the language server's diagram server sends (sprotty-vscode's LSP glue:
// diagram/accept both ways, diagram/didClose, diagram/openInTextEditor to reveal a node's source).
// One panel, which follows the active editor while it shows a tree file.
import * as vscode from 'vscode';
import { LanguageClient } from 'vscode-languageclient/node';
import { LspWebviewPanelManager } from 'sprotty-vscode/lib/lsp';

/** The Sprotty diagram type the server answers (org.miron.lsp.diagram). */
const DIAGRAM_TYPE = 'miron-diagram';
/** The files the server draws: BT (v3/v4 XML, woven .ext.xml) and MIRoN models. */
const DRAWN = ['bt', 'miron'];

export class DiagramPanels implements vscode.Disposable {
    private manager: LspWebviewPanelManager | undefined;
    private managerClient: LanguageClient | undefined;
    private readonly following: vscode.Disposable;

    constructor(private readonly extensionUri: vscode.Uri, private readonly client: () => Promise<LanguageClient | undefined>) {
        this.following = vscode.window.onDidChangeActiveTextEditor((editor) => void this.follow(editor));
    }

    /** Opens (or points) the panel at a file: the one given, else the active editor's. */
    async show(target?: unknown): Promise<void> {
        const uri = target instanceof vscode.Uri ? target : vscode.window.activeTextEditor?.document.uri;
        if (!uri) {
            void vscode.window.showInformationMessage('MIRoN: open a behaviour tree or a .miron file to see its diagram.');
            return;
        }
        const manager = await this.managerFor();
        if (!manager) {
            void vscode.window.showErrorMessage('MIRoN: the language server is not running: no diagram.');
            return;
        }
        await manager.openDiagram(uri, { diagramType: DIAGRAM_TYPE, reveal: true, preserveFocus: true });
    }

    private async follow(editor: vscode.TextEditor | undefined): Promise<void> {
        if (!editor || !DRAWN.includes(editor.document.languageId) || !this.manager || this.manager.endpoints.length === 0) {
            return;
        }
        const shown = this.manager.endpoints[0].diagramIdentifier?.uri;
        if (shown !== editor.document.uri.toString()) {
            await this.manager.openDiagram(editor.document.uri, { diagramType: DIAGRAM_TYPE, reveal: false, preserveFocus: true });
        }
    }

    /** The panel manager of the running client; a restarted server gets a new one (the old panel closes). */
    private async managerFor(): Promise<LspWebviewPanelManager | undefined> {
        const client = await this.client();
        if (!client) {
            return undefined;
        }
        if (this.manager && this.managerClient !== client) {
            this.closePanels();
        }
        if (!this.manager) {
            this.manager = new LspWebviewPanelManager({
                extensionUri: this.extensionUri,
                languageClient: client,
                defaultDiagramType: DIAGRAM_TYPE,
                singleton: true,
            });
            this.managerClient = client;
        }
        return this.manager;
    }

    private closePanels(): void {
        for (const endpoint of [...(this.manager?.endpoints ?? [])]) {
            const container = endpoint.webviewContainer as vscode.WebviewPanel;
            container.dispose();
        }
        this.manager = undefined;
        this.managerClient = undefined;
    }

    dispose(): void {
        this.following.dispose();
        this.closePanels();
    }
}
