/** The demonstrators' reasoner: decaying likelihood-ratio evidence per belief, estimates around a reference. */
package org.miron.runtime.roqme.reasoner;
