package org.miron.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.IEObjectDescription;

import com.google.inject.Inject;

/**
 * RoQME's and MIRoN's scope provider (MIRoN's generated one extends it). Scopes come from the
 * delegate, {@link FileScopeProvider}: the linker records imported names on that one.
 */
public class RoqmeScopeProvider extends AbstractRoqmeScopeProvider {

    @Inject
    private FileScopeProvider files;

    /** All descriptions visible in a resource, own and imported, of any type (for messages). */
    public List<IEObjectDescription> visible(Resource resource) {
        return files.visible(resource);
    }
}
