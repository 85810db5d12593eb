package org.miron.dsl.naming;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.QualifiedName;

/**
 * References are written a.b (variables, trees, nodes) or a::b::c (enum literals), and the
 * grammar decides which delimiter a reference uses; both split into the same segments, so
 * roqme::AvailableSpace::HIGH finds the literal AvailableSpace::HIGH imported as roqme.
 */
public class DslQualifiedNameConverter extends IQualifiedNameConverter.DefaultImpl {

    @Override
    public QualifiedName toQualifiedName(String text) {
        if (text == null || text.isEmpty()) {
            return QualifiedName.EMPTY;
        }
        List<String> segments = new ArrayList<>();
        for (String part : text.split("::|\\.", -1)) {
            segments.add(part.trim());
        }
        return QualifiedName.create(segments);
    }
}
