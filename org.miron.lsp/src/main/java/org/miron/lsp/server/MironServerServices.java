package org.miron.lsp.server;

import org.eclipse.xtext.ide.server.commands.IExecutableCommandService;
import org.eclipse.xtext.service.AbstractGenericModule;

/** MIRoN language services of the server that depend on the generators. */
public class MironServerServices extends AbstractGenericModule {

    public Class<? extends IExecutableCommandService> bindIExecutableCommandService() {
        return GenerateCommandService.class;
    }
}
