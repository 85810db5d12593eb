/**
 * Expressions and patterns compiled from the runtime model: value nodes (unknown is null and
 * propagates), event nodes with their own state, sliding windows as computed slots, and timers' cron.
 */
package org.miron.runtime.roqme.expr;
