package org.miron.diagram;

import org.eclipse.sprotty.SNode;

/**
 * A Sprotty node that may link to another frame: a SubTree call to the tree it calls, a variant to
 * the tree it puts in place (the SVG makes it a link, a Sprotty client gets it as {@code link}).
 */
public class TreeSNode extends SNode {
    private String link;
    /** A SubTree call: whether its tree is drawn below it (Sprotty's expandable feature); else null. */
    private Boolean expanded;

    /** The id of the frame this node links to, or null. */
    public String getLink() {
        return link;
    }

    public void setLink(String link) {
        this.link = link;
    }

    public Boolean getExpanded() {
        return expanded;
    }

    public void setExpanded(Boolean expanded) {
        this.expanded = expanded;
    }
}
