// The diagram webview: Sprotty drawing the models the MIRoN language server sends (laid out there
// by ELK, as `miron render` draws them), through sprotty-vscode's webview starter. Bundled by
// esbuild into pack/webview.js (npm run bundle), where sprotty-vscode's panel manager loads it.
import 'reflect-metadata';
import { Container, ContainerModule, decorate, injectable } from 'inversify';
import { VNode } from 'snabbdom';
import {
    configureModelElement, configureViewerOptions, expandFeature, IView, IViewArgs, loadDefaultModules, MouseListener,
    openFeature, PolylineEdgeView, RenderingContext, SEdgeImpl, SGraphImpl, SGraphView, SLabelImpl,
    SModelElementImpl, SNodeImpl, setClass, svg, TYPES,
} from 'sprotty';
import { Action, CollapseExpandAction, Point } from 'sprotty-protocol';
import { SprottyDiagramIdentifier, SprottyStarter } from 'sprotty-vscode-webview';
import { DIAGRAM_STYLE } from './style';

/** The node kinds of org.miron.diagram's ShapeKind: model type node:<kind>. */
const KINDS = ['control', 'decorator', 'action', 'condition', 'subtree', 'builtin', 'varpoint', 'variant'];
const LABELS = ['heading', 'title', 'type', 'port', 'note'];
const EDGES = ['child', 'call', 'variant', 'varpoint'];

/** A tree node; a SubTree call also says whether its tree is drawn below it. */
class TreeNode extends SNodeImpl {
    expanded?: boolean;
    link?: string;
}

/** A tree's frame: its box; the heading is a label. */
class FrameView implements IView {
    render(frame: Readonly<SNodeImpl>, context: RenderingContext): VNode {
        return svg('g', { 'class-miron-frame': true },
            svg('rect', { 'class-frame-box': true, width: frame.size.width, height: frame.size.height, rx: 4 }),
            ...context.renderChildren(frame)) as unknown as VNode;
    }
}

/** A tree node: its outline by kind (as the SVG writer draws it), its labels, an expand toggle on calls. */
class TreeNodeView implements IView {
    render(node: Readonly<TreeNode>, context: RenderingContext): VNode {
        const kind = node.type.substring(node.type.indexOf(':') + 1);
        const w = node.size.width;
        const h = node.size.height;
        const classes: Record<string, boolean> = {
            'class-miron-node': true, [`class-node-${kind}`]: true, 'class-selected': node.selected,
        };
        const shape = kind === 'decorator'
            ? svg('polygon', { 'class-shape': true, points: `8,0 ${w - 8},0 ${w},8 ${w},${h - 8} ${w - 8},${h} 8,${h} 0,${h - 8} 0,8` })
            : svg('rect', { 'class-shape': true, width: w, height: h, rx: kind === 'condition' ? Math.min(h / 2, 18) : kind === 'control' ? 1 : kind === 'subtree' ? 3 : 6 });
        const parts = [shape];
        if (node.expanded !== undefined && node.expanded !== null) {
            parts.push(svg('g', { 'class-miron-expand': true, transform: `translate(${w - 10},-8)` },
                svg('rect', { 'class-miron-expand': true, width: 16, height: 16, rx: 3 }),
                svg('text', { 'class-miron-expand': true, x: 8, y: 12, 'text-anchor': 'middle' }, node.expanded ? '−' : '+')));
        }
        return svg('g', classes, ...parts, ...context.renderChildren(node)) as unknown as VNode;
    }
}

/** A label, its position its top-left corner (the baseline one font size lower), as the SVG writer has it. */
class LabelView implements IView {
    render(label: Readonly<SLabelImpl>): VNode {
        const type = label.type.substring(label.type.indexOf(':') + 1);
        const size = type === 'heading' ? 13 : type === 'title' ? 12 : 11;
        return svg('text', { 'class-miron-label': true, [`class-label-${type}`]: true, y: size }, label.text) as unknown as VNode;
    }
}

/** The edges drawn with an arrowhead at their target, as the SVG writer's marker: SubTree call → called tree, varpoint → variant. */
const ARROWED = ['call', 'variant'];

/** An edge with its kind as a class (edge-call, edge-variant... are dashed); calls and variants end in an arrowhead. */
class TypedEdgeView extends PolylineEdgeView {
    override render(edge: Readonly<SEdgeImpl>, context: RenderingContext, args?: IViewArgs): VNode | undefined {
        const vnode = super.render(edge, context, args);
        if (vnode) {
            setClass(vnode, 'edge-' + edgeKind(edge), true);
        }
        return vnode;
    }

    // The SVG writer's marker (a 10 by 10 triangle, 8 stroke widths long) as a path: its tip on the
    // route's end, turned along the last segment that has a length.
    protected override renderAdditionals(edge: SEdgeImpl, segments: Point[], context: RenderingContext): VNode[] {
        const additionals = super.renderAdditionals(edge, segments, context);
        if (!ARROWED.includes(edgeKind(edge)) || segments.length < 2) {
            return additionals;
        }
        const tip = segments[segments.length - 1];
        let from = segments.length - 2;
        while (from > 0 && Math.hypot(tip.x - segments[from].x, tip.y - segments[from].y) < 0.5) {
            from--;
        }
        const angle = Math.atan2(tip.y - segments[from].y, tip.x - segments[from].x) * 180 / Math.PI;
        return [...additionals, svg('path', {
            'class-miron-arrow': true, d: 'M 0,0 L -10.4,-5.2 L -10.4,5.2 Z',
            transform: `translate(${tip.x},${tip.y}) rotate(${angle})`,
        }) as unknown as VNode];
    }
}

function edgeKind(edge: Readonly<SEdgeImpl>): string {
    return edge.type.substring(edge.type.indexOf(':') + 1);
}

/** A click on a call's +/− asks the server to draw its tree below it, or not. */
class ExpandToggle extends MouseListener {
    override mouseDown(target: SModelElementImpl, event: MouseEvent): (Action | Promise<Action>)[] {
        const toggle = event.target instanceof Element && event.target.closest('.miron-expand');
        const parent = 'parent' in target ? (target as { parent: unknown }).parent : undefined;
        const node = target instanceof TreeNode ? target : parent instanceof TreeNode ? parent : undefined;
        if (!toggle || !node || node.expanded === undefined) {
            return [];
        }
        return [CollapseExpandAction.create(node.expanded ? { collapseIds: [node.id] } : { expandIds: [node.id] })];
    }
}

for (const view of [FrameView, TreeNodeView, LabelView]) {
    decorate(injectable(), view);
}
decorate(injectable(), ExpandToggle);
decorate(injectable(), TypedEdgeView);

class MironSprottyStarter extends SprottyStarter {
    protected createContainer(identifier: SprottyDiagramIdentifier): Container {
        const container = new Container();
        loadDefaultModules(container);
        container.load(new ContainerModule((bind, unbind, isBound, rebind) => {
            const context = { bind, unbind, isBound, rebind };
            configureModelElement(context, 'graph', SGraphImpl, SGraphView);
            configureModelElement(context, 'tree', SNodeImpl, FrameView);
            for (const kind of KINDS) {
                configureModelElement(context, `node:${kind}`, TreeNode, TreeNodeView, { enable: [openFeature, expandFeature] });
            }
            for (const label of LABELS) {
                configureModelElement(context, `label:${label}`, SLabelImpl, LabelView);
            }
            for (const edge of EDGES) {
                configureModelElement(context, `edge:${edge}`, SEdgeImpl, TypedEdgeView);
            }
            bind(TYPES.MouseListener).to(ExpandToggle);
            // The server lays the diagram out (ELK): the client neither measures nor moves.
            configureViewerOptions(context, {
                needsClientLayout: false,
                needsServerLayout: true,
                baseDiv: identifier.clientId,
                hiddenDiv: identifier.clientId + '_hidden',
            });
        }));
        return container;
    }
}

const style = document.createElement('style');
style.textContent = DIAGRAM_STYLE;
document.head.appendChild(style);
new MironSprottyStarter().start();
