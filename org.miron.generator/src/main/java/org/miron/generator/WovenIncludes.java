package org.miron.generator;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.miron.bt.bt.BTModel;
import org.miron.bt.scoping.BtGlobalScopeProvider;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;
import org.miron.dsl.miron.BehaviorTreeLiteral;

/**
 * The includes of the woven tree, relative to where it is written: those of the copied files, then
 * the files of variant trees not reachable through them; never a copied file, never twice. An
 * included file is loaded as it is, so it must already be in the woven tree's format.
 */
final class WovenIncludes {
    private final List<GenerationError> errors;
    private final int format;
    private final URI wovenTree;

    WovenIncludes(List<GenerationError> errors, int format, URI wovenTree) {
        this.errors = errors;
        this.format = format;
        this.wovenTree = wovenTree;
    }

    /** The include paths of a woven tree copying the files woven, weaving the varpoints bound. */
    List<String> of(Set<Resource> woven, List<SampledVariationPoint> bound) {
        Set<URI> uris = new LinkedHashSet<>();
        Set<URI> wovenUris = new LinkedHashSet<>();
        woven.forEach(r -> wovenUris.add(r.getURI()));
        for (Resource r : woven) {
            for (URI uri : BtGlobalScopeProvider.includesOf(r)) {
                if (!wovenUris.contains(uri)) {
                    uris.add(uri);
                }
            }
        }
        Set<URI> reachable = new LinkedHashSet<>(wovenUris);
        ResourceSet resourceSet = woven.iterator().next().getResourceSet();
        for (URI uri : uris) {
            reachable.add(uri);
            Resource r = resourceSet.getResource(uri, true);
            checkVersion(r);
            BtTrees.includedResources(r).forEach(included -> reachable.add(included.getURI()));
        }
        for (SampledVariationPoint vp : bound) {
            if (!vp.isEnum()) {
                continue;
            }
            for (var literal : vp.literals) {
                if (literal instanceof BehaviorTreeLiteral bt && bt.getReference() != null
                        && !bt.getReference().eIsProxy()) {
                    Resource r = bt.getReference().eResource();
                    if (!reachable.contains(r.getURI())) {
                        checkVersion(r);
                        uris.add(r.getURI());
                        reachable.add(r.getURI());
                        BtTrees.includedResources(r).forEach(included -> reachable.add(included.getURI()));
                    }
                }
            }
        }
        return uris.stream().map(uri -> OutputLocation.relative(uri, wovenTree)).toList();
    }

    private void checkVersion(Resource included) {
        if (!included.getContents().isEmpty() && included.getContents().get(0) instanceof BTModel model) {
            int version = BtFormats.version(model);
            if (version != format) {
                errors.add(new GenerationError(model, "the woven tree (BehaviorTree.CPP " + format + ") includes "
                        + included.getURI().lastSegment() + ", a BehaviorTree.CPP " + version
                        + " file: convert it with `miron convert --to " + format + "` or weave with --bt-format "
                        + version));
            }
        }
    }
}
