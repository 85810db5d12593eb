/**
 * MIRoN in the Eclipse workspace, on org.eclipse.core.resources alone (no Xtext UI, EMF UI, LSP4E or
 * TM4E, which an Eclipse from Maven Central does not have): the project nature
 * {@code org.miron.eclipse.nature}, the incremental builder {@code org.miron.eclipse.builder}, its
 * problem markers {@code org.miron.eclipse.problem}, and the commands "Add MIRoN Nature" and
 * "Generate MIRoN artefacts". Checking and generation go through the toolchain's headless core
 * ({@code ModelLoader}, {@code BatchGeneration}), the code `miron check` and `miron generate` run,
 * so a marker says what the command line says and generated/ holds the bytes it writes.
 */
package org.miron.eclipse.builder;
