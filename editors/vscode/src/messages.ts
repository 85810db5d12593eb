// The server's window/showMessage notifications. While a command of ours waits for its answer,
// they are held back: the answer's own message is then shown once, by the extension, with its
// buttons ("Open generated files"), instead of twice.
import * as vscode from 'vscode';
import { MessageType, ShowMessageParams } from 'vscode-languageclient/node';

export class ServerMessages {
    private waiting = 0;
    private held: ShowMessageParams[] = [];

    /** Shows `params` now, or later if a command is waiting for its answer. */
    handle(params: ShowMessageParams): void {
        if (this.waiting > 0) {
            this.held.push(params);
        } else {
            show(params);
        }
    }

    /** Runs `request`, holding the server's messages back until it answers. */
    async around<T>(request: () => Thenable<T>, messageOf: (answer: T) => string | undefined): Promise<T> {
        this.waiting++;
        let answer: T | undefined;
        try {
            answer = await request();
            return answer;
        } finally {
            this.waiting--;
            const own = answer === undefined ? undefined : messageOf(answer);
            const i = own === undefined ? -1 : this.held.findIndex((m) => m.message === own);
            if (i >= 0) {
                this.held.splice(i, 1);
            }
            if (this.waiting === 0) {
                const rest = this.held;
                this.held = [];
                rest.forEach(show);
            }
        }
    }
}

function show(params: ShowMessageParams): void {
    switch (params.type) {
        case MessageType.Error:
            void vscode.window.showErrorMessage(params.message);
            break;
        case MessageType.Warning:
            void vscode.window.showWarningMessage(params.message);
            break;
        default:
            void vscode.window.showInformationMessage(params.message);
    }
}
