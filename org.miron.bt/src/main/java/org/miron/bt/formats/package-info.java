/**
 * Conversion of behaviour trees between the XML formats of BehaviorTree.CPP 3 and 4 (`miron
 * convert`, and the weaver for `miron generate --bt-format`): {@link
 * org.miron.bt.formats.BtFormatConverter#convert} changes a model in place and returns a {@link
 * org.miron.bt.formats.Conversion}, which lists the elements without equivalent ({@link
 * org.miron.bt.formats.ConversionProblem}, printed as {@code file:line:col: error [code]: message})
 * or, on success, the nodes it replaced; {@link org.miron.bt.formats.BtFormatConverter#text} prints
 * the result. The rules per direction are in V3ToV4 and V4ToV3, the BlackboardCheck ⇄ Precondition
 * encoding in BlackboardChecks. (Named after the formats, not "convert": Xtext's
 * {@code org.miron.bt.conversion} beside it holds the grammar's value converters.)
 */
package org.miron.bt.formats;
