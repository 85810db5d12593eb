// The status-bar item of the language server: starting, running or failed; a click shows the
// server's output.
import * as vscode from 'vscode';

export type ServerStatus = 'starting' | 'running' | 'failed' | 'stopped';

export class StatusItem implements vscode.Disposable {
    private readonly item: vscode.StatusBarItem;
    private current: ServerStatus = 'stopped';

    constructor() {
        this.item = vscode.window.createStatusBarItem('miron.status', vscode.StatusBarAlignment.Left, 10);
        this.item.name = 'MIRoN Language Server';
        this.item.command = 'miron.showOutput';
    }

    get status(): ServerStatus {
        return this.current;
    }

    /** Shows `status`; `detail` (e.g. the error) goes into the tooltip. */
    set(status: ServerStatus, detail?: string): void {
        this.current = status;
        const icon = { starting: '$(sync~spin)', running: '$(check)', failed: '$(error)', stopped: '$(circle-slash)' }[status];
        this.item.text = `${icon} MIRoN`;
        this.item.tooltip = `MIRoN language server: ${status}${detail ? ` (${detail})` : ''}. Click to show its output.`;
        this.item.accessibilityInformation = { label: `MIRoN language server ${status}` };
        this.item.backgroundColor = status === 'failed' ? new vscode.ThemeColor('statusBarItem.errorBackground') : undefined;
        this.item.show();
    }

    dispose(): void {
        this.item.dispose();
    }
}
