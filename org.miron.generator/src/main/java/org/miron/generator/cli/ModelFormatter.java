package org.miron.generator.cli;

import java.util.List;

import org.eclipse.xtext.formatting2.FormatterPreferenceKeys;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccess;
import org.eclipse.xtext.formatting2.regionaccess.ITextReplacement;
import org.eclipse.xtext.formatting2.regionaccess.TextRegionAccessBuilder;
import org.eclipse.xtext.preferences.MapBasedPreferenceValues;
import org.eclipse.xtext.resource.XtextResource;

/** Runs a language's Xtext formatter over a whole parsed file and returns the new text. */
public final class ModelFormatter {
    private ModelFormatter() {
    }

    public static String format(XtextResource resource) {
        IFormatter2 formatter = resource.getResourceServiceProvider().get(IFormatter2.class);
        ITextRegionAccess regions = resource.getResourceServiceProvider().get(TextRegionAccessBuilder.class)
                .forNodeModel(resource).create();
        MapBasedPreferenceValues preferences = new MapBasedPreferenceValues();
        preferences.put(FormatterPreferenceKeys.indentation, "  ");
        preferences.put(FormatterPreferenceKeys.lineSeparator, "\n");
        FormatterRequest request = new FormatterRequest();
        request.setTextRegionAccess(regions);
        request.setPreferences(preferences);
        request.setFormatUndefinedHiddenRegionsOnly(false);
        List<ITextReplacement> replacements = formatter.format(request);
        String text = regions.getRewriter().renderToString(replacements);
        return text.endsWith("\n") ? text : text + "\n";
    }
}
