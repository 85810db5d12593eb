package org.miron.eclipse.builder;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.core.expressions.IEvaluationContext;
import org.eclipse.core.runtime.Adapters;

/** What a command applies to: the adaptable elements of the selection, else the active editor's input. */
final class Selections {
    private Selections() {
    }

    static <T> List<T> of(Object applicationContext, Class<T> type) {
        Set<T> found = new LinkedHashSet<>();
        if (applicationContext instanceof IEvaluationContext context) {
            Object selection = context.getVariable("selection");
            Iterable<?> elements = selection instanceof Iterable<?> iterable ? iterable : List.of();
            for (Object element : elements) {
                add(found, element, type);
            }
            if (found.isEmpty()) {
                add(found, context.getVariable("activeEditorInput"), type);
            }
        }
        return new ArrayList<>(found);
    }

    private static <T> void add(Set<T> found, Object element, Class<T> type) {
        T adapted = element == null ? null : Adapters.adapt(element, type);
        if (adapted != null) {
            found.add(adapted);
        }
    }
}
