/**
 * The RoQME QoS Metrics Provider (docs/roqme-provider.md): reads a generated {@code name.roqme.json},
 * evaluates its observations on the contexts it receives and turns the fired observations into
 * estimates of its properties, on a live clock ({@link org.miron.runtime.roqme.LiveProvider}) or a
 * virtual one ({@link org.miron.runtime.roqme.Replay}). Plain Java and Jackson: no Xtext or EMF.
 */
package org.miron.runtime.roqme;
