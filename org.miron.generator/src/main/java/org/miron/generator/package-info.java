/**
 * The MIRoN generators (docs/generators.md): analysis, weaving and the emitters of the woven tree,
 * name.mzn, name.dzn and name.io.json. Xtend only where the class is mostly template text
 * (MiniZincGenerator, DznGenerator, ExpressionToMiniZinc); Java 17 for the rest. Expressions are
 * dispatched on EMF's generated switches (RoqmeSwitch, MironSwitch), whose defaultCase reports an
 * element no case handles instead of translating it silently.
 */
package org.miron.generator;
