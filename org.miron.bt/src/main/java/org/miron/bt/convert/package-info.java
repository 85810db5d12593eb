/**
 * Conversion of behaviour trees between the XML formats of BehaviorTree.CPP 3 and 4 (`miron
 * convert`, and the weaver for `miron generate --bt-format`): {@link
 * org.miron.bt.convert.BtFormatConverter#convert} changes a model in place and returns a {@link
 * org.miron.bt.convert.Conversion}, which lists the elements without equivalent ({@link
 * org.miron.bt.convert.ConversionProblem}, printed as {@code file:line:col: error [code]: message})
 * or, on success, the nodes it replaced; {@link org.miron.bt.convert.BtFormatConverter#text} prints
 * the result. The rules per direction are in V3ToV4 and V4ToV3, the BlackboardCheck ⇄ Precondition
 * encoding in BlackboardChecks.
 */
package org.miron.bt.convert;
