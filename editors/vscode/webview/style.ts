// The diagram's look in the webview: the colours of org.miron.diagram's SVG writer, light or dark as
// VS Code's theme is (its body classes), text in the editor's font and colours (its CSS variables).

const LIGHT = `--frame:#f6f8fa;--frame-line:#d0d7de;--edge:#57606a;--muted:#5b6570;
  --control:#dbeafe;--control-line:#1d4ed8;--decorator:#ede9fe;--decorator-line:#6d28d9;--action:#dcfce7;
  --action-line:#15803d;--condition:#fef9c3;--condition-line:#a16207;--subtree:#e0f2fe;--subtree-line:#0369a1;
  --builtin:#f3f4f6;--builtin-line:#6b7280;--varpoint:#ffedd5;--varpoint-line:#c2410c;--variant:#fff7ed;
  --variant-line:#ea580c;--woven:#0f766e;`;
const DARK = `--frame:#161b22;--frame-line:#30363d;--edge:#8b949e;--muted:#9da7b3;--control:#172554;
  --control-line:#60a5fa;--decorator:#2e1065;--decorator-line:#a78bfa;--action:#052e16;--action-line:#4ade80;
  --condition:#422006;--condition-line:#facc15;--subtree:#082f49;--subtree-line:#38bdf8;--builtin:#1f2937;
  --builtin-line:#9ca3af;--varpoint:#431407;--varpoint-line:#fb923c;--variant:#2a1508;--variant-line:#fdba74;
  --woven:#2dd4bf;`;

export const DIAGRAM_STYLE = `
body { ${LIGHT} margin:0; padding:0; height:100vh; overflow:hidden;
  background:var(--vscode-editor-background); color:var(--vscode-editor-foreground); }
body.vscode-dark, body.vscode-high-contrast:not(.vscode-high-contrast-light) { ${DARK} }
body > div, body > div > div:first-child { height:100%; }
svg.sprotty-graph { width:100%; height:100%; outline:none; border:none; }
.miron-label { fill:var(--vscode-editor-foreground); font-family:var(--vscode-editor-font-family, monospace);
  font-size:11px; white-space:pre; user-select:none; }
.label-title { font-size:12px; font-weight:bold; }
.label-heading { font-size:13px; font-weight:bold; }
.label-type, .label-note { fill:var(--muted); font-style:italic; }
.parameter { fill:var(--varpoint-line); font-weight:bold; }
.miron-frame > .frame-box { fill:var(--frame); stroke:var(--frame-line); }
.miron-node > .shape { stroke-width:1.5; }
.node-control > .shape { fill:var(--control); stroke:var(--control-line); }
.node-decorator > .shape { fill:var(--decorator); stroke:var(--decorator-line); }
.node-action > .shape { fill:var(--action); stroke:var(--action-line); }
.node-condition > .shape { fill:var(--condition); stroke:var(--condition-line); }
.node-subtree > .shape { fill:var(--subtree); stroke:var(--subtree-line); }
.node-builtin > .shape { fill:var(--builtin); stroke:var(--builtin-line); stroke-dasharray:4 2; }
.node-varpoint > .shape { fill:var(--varpoint); stroke:var(--varpoint-line); stroke-dasharray:6 3; }
.node-variant > .shape { fill:var(--variant); stroke:var(--variant-line); }
.woven > .shape { stroke:var(--woven); stroke-width:3; }
.varpoint-target > .shape { stroke:var(--varpoint-line); stroke-width:3.5; }
.miron-node.selected > .shape { stroke:var(--vscode-focusBorder); stroke-width:3; }
.miron-node { cursor:pointer; }
rect.miron-expand { fill:var(--vscode-button-background); }
text.miron-expand { fill:var(--vscode-button-foreground); font-size:13px; font-weight:bold; }
.sprotty-edge { fill:none; stroke:var(--edge); stroke-width:1.3; }
.sprotty-edge.edge-call, .sprotty-edge.edge-variant { stroke-dasharray:5 4; }
.sprotty-edge.edge-varpoint, .sprotty-edge.edge-variant { stroke:var(--varpoint-line); }
.sprotty-edge > .miron-arrow { fill:var(--edge); stroke:none; stroke-dasharray:none; }
.sprotty-edge.edge-variant > .miron-arrow { fill:var(--varpoint-line); }
.sprotty-status { position:absolute; left:8px; bottom:6px; display:flex; gap:6px;
  font-family:var(--vscode-font-family); font-size:12px; }
.sprotty-status-message.error, .sprotty-status-message.fatal { color:var(--vscode-errorForeground); }
.sprotty-hidden { width:0; height:0; position:absolute; visibility:hidden; }
`;
