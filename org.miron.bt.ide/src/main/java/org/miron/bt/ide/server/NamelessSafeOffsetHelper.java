package org.miron.bt.ide.server;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.resource.EObjectAtOffsetHelper;
import org.eclipse.xtext.resource.XtextResource;

/**
 * Xtext's element-at-offset lookup for definition, references and rename, also where a
 * half-written file has a token that belongs to no element: Xtext asks that missing element for
 * its name attribute ("Cannot invoke EObject.eClass() because object is null"); there is none to
 * navigate from, so the answer is no element.
 */
public class NamelessSafeOffsetHelper extends EObjectAtOffsetHelper {

    @Override
    public EObject getElementWithNameAt(XtextResource resource, int offset) {
        if (resource != null && offset >= 0 && resource.getParseResult() != null
                && resolveCrossReferencedElementAt(resource, offset) == null && resolveElementAt(resource, offset) == null) {
            return null;
        }
        return super.getElementWithNameAt(resource, offset);
    }
}
