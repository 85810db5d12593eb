package org.miron.bt.formatting2;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.formatting2.FormatterPreferenceKeys;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccess;
import org.eclipse.xtext.formatting2.regionaccess.ITextReplacement;
import org.eclipse.xtext.formatting2.regionaccess.TextRegionAccessBuilder;
import org.eclipse.xtext.preferences.MapBasedPreferenceValues;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.serializer.impl.Serializer;

/**
 * The one printer of the MIRoN languages: their Xtext formatter, two-space indentation, '\n' line
 * ends, over a parsed file ({@link #format}, `miron format`) or over a model built in memory and
 * written by the language's serializer ({@link #print}, the woven tree of `miron generate`).
 */
public final class BtFormatting {
    private BtFormatting() {
    }

    /** The parsed file formatted, comments kept. */
    public static String format(XtextResource resource) {
        IResourceServiceProvider language = resource.getResourceServiceProvider();
        return format(language.get(TextRegionAccessBuilder.class).forNodeModel(resource).create(), language);
    }

    /**
     * A model with no text of its own (built or changed in memory), serialized and formatted. It
     * must be in an XtextResource of its language: cross-references are written by the names in
     * scope there, so its URI decides how relative includes resolve.
     */
    public static String print(EObject model) {
        IResourceServiceProvider language = ((XtextResource) model.eResource()).getResourceServiceProvider();
        return format(language.get(Serializer.class).serializeToRegions(model), language);
    }

    private static String format(ITextRegionAccess regions, IResourceServiceProvider language) {
        MapBasedPreferenceValues preferences = new MapBasedPreferenceValues();
        preferences.put(FormatterPreferenceKeys.indentation, "  ");
        preferences.put(FormatterPreferenceKeys.lineSeparator, "\n");
        FormatterRequest request = new FormatterRequest();
        request.setTextRegionAccess(regions);
        request.setPreferences(preferences);
        request.setFormatUndefinedHiddenRegionsOnly(false);
        List<ITextReplacement> replacements = language.get(IFormatter2.class).format(request);
        String text = regions.getRewriter().renderToString(replacements);
        return text.endsWith("\n") ? text : text + "\n";
    }
}
