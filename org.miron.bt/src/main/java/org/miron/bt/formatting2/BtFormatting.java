package org.miron.bt.formatting2;

import java.util.List;

import org.eclipse.xtext.formatting2.FormatterPreferenceKeys;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccess;
import org.eclipse.xtext.formatting2.regionaccess.ITextReplacement;
import org.eclipse.xtext.formatting2.regionaccess.TextRegionAccessBuilder;
import org.eclipse.xtext.preferences.MapBasedPreferenceValues;
import org.eclipse.xtext.resource.XtextResource;

/**
 * Runs the Xtext formatter of a resource's language over the whole parsed file and returns the
 * new text: two-space indentation, '\n' line ends. Works for any of the MIRoN languages.
 */
public final class BtFormatting {
    private BtFormatting() {
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
