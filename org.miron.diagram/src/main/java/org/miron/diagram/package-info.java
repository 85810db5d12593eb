/**
 * Behaviour-tree diagrams: what a BT file, a woven {@code .ext.xml} or a MIRoN model looks like,
 * as a Sprotty model laid out by ELK and as a standalone SVG.
 *
 * <p>The pipeline has three steps, each a class with one job: {@link org.miron.diagram.BtShapes}
 * and {@link org.miron.diagram.MironShapes} turn a model into a {@link org.miron.diagram.Diagram}
 * of {@link org.miron.diagram.Frame}s (one per tree) holding {@link org.miron.diagram.Shape}s (one
 * per tree node, kinds by {@link org.miron.diagram.ShapeKind}); {@link org.miron.diagram.DiagramLayout}
 * sizes the shapes from their labels ({@code Metrics}: a monospace font, so no browser is needed to
 * measure text) and lays each frame out with ELK layered, top-down, children in document order,
 * then the frames with the calls between them, into a Sprotty {@code SGraph};
 * {@link org.miron.diagram.SvgWriter} draws that model. The same model would feed a Sprotty client,
 * so the command line's SVG, the demo report and the live monitor page show one layout.
 *
 * <p>Why the shapes step: the run-time views (demo report, live monitor) draw a tree expanded as the
 * executor runs it ({@link org.miron.diagram.BtShapes#expanded}), numbered as the executor numbers
 * its status messages, while editors draw every tree of a file once; both share the layout and
 * the writer.
 *
 * <p>This module depends on the BT and MIRoN languages only: the CLI, the runtime views and the
 * language server use it, nothing below them does.
 */
package org.miron.diagram;
