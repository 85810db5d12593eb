package org.miron.dsl.resource;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.impl.DefaultResourceDescriptionStrategy;
import org.eclipse.xtext.util.IAcceptor;
import org.miron.dsl.roqme.RoqmeModel;

/** Exports what the default strategy exports, plus the model root's {@link ModelSummary}. */
public class DslResourceDescriptionStrategy extends DefaultResourceDescriptionStrategy {

    @Override
    public boolean createEObjectDescriptions(EObject eObject, IAcceptor<IEObjectDescription> acceptor) {
        if (eObject instanceof RoqmeModel && eObject.eContainer() == null) {
            acceptor.accept(ModelSummary.describe((RoqmeModel) eObject));
        }
        return super.createEObjectDescriptions(eObject, acceptor);
    }
}
