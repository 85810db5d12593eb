package org.miron.bt.validation;

import java.util.List;

import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BtPackage;

/**
 * Maps an offset in a decoded attribute value (what the script parser sees) to the offset in the
 * file: past the opening quote, and past each entity ({@code &amp;amp;} is one character of the
 * script, five of the file).
 */
final class ScriptPositions {
    private final int[] fileOffsets;

    private ScriptPositions(int[] fileOffsets) {
        this.fileOffsets = fileOffsets;
    }

    /** Null when the attribute has no node model (built in memory). */
    static ScriptPositions of(Attribute attribute) {
        List<INode> nodes = NodeModelUtils.findNodesForFeature(attribute, BtPackage.Literals.ATTRIBUTE__VALUE);
        if (nodes.isEmpty()) {
            return null;
        }
        INode node = nodes.get(0);
        String raw = node.getText();
        int base = node.getOffset() + (node.getText().length() - node.getText().stripLeading().length());
        raw = raw.strip();
        int decodedLength = attribute.getValue().length();
        int[] offsets = new int[decodedLength + 1];
        int rawIndex = 1; // past the opening quote
        for (int i = 0; i <= decodedLength; i++) {
            offsets[i] = base + Math.min(rawIndex, Math.max(0, raw.length() - 1));
            if (rawIndex < raw.length() && raw.charAt(rawIndex) == '&') {
                int semicolon = raw.indexOf(';', rawIndex);
                rawIndex = semicolon < 0 ? rawIndex + 1 : semicolon + 1;
            } else {
                rawIndex++;
            }
        }
        return new ScriptPositions(offsets);
    }

    int fileOffset(int scriptOffset) {
        return fileOffsets[Math.max(0, Math.min(scriptOffset, fileOffsets.length - 1))];
    }

    /** The length in the file of the script range [offset, offset + length), at least 1. */
    int fileLength(int scriptOffset, int length) {
        return Math.max(1, fileOffset(scriptOffset + length) - fileOffset(scriptOffset));
    }
}
