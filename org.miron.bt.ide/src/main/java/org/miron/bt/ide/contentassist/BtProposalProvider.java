package org.miron.bt.ide.contentassist;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;

/** BT completion. */
public class BtProposalProvider extends IdeContentProposalProvider {
}
