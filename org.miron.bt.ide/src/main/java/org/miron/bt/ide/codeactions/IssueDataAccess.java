package org.miron.bt.ide.codeactions;

/** The first string of a diagnostic's issue data, for clients and tests of the quick fixes. */
public final class IssueDataAccess {

    private IssueDataAccess() {
    }

    public static String first(Object data) {
        var values = IssueData.of(data);
        return values.isEmpty() ? null : values.get(0);
    }
}
