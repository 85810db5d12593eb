package org.miron.bt.ide;

import static org.junit.Assert.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.antlr.runtime.ANTLRStringStream;
import org.antlr.runtime.Token;
import org.junit.Test;
import org.miron.bt.ide.contentassist.antlr.BtContentAssistLexer;
import org.miron.bt.ide.contentassist.antlr.lexer.InternalBtLexer;
import org.miron.bt.parser.BtLexer;

/** The content-assist lexer cuts a file into the same tokens as the runtime lexer. */
public class ContentAssistLexerTest {
    private static final String TEXT = "<root><TreeNodesModel><Action ID=\"Timeout\"><input_port name=\"x\"/></Action>"
            + "</TreeNodesModel><BehaviorTree ID=\"T\"><Timeout msec=\"1\"><Action ID=\"a\"/></Timeout></BehaviorTree></root>";

    @Test
    public void treeNodesModelIsOneToken() {
        List<String> contentAssist = texts(new BtContentAssistLexer(new ANTLRStringStream(TEXT)));
        assertEquals("<TreeNodesModel><Action ID=\"Timeout\"><input_port name=\"x\"/></Action></TreeNodesModel>",
                contentAssist.get(3));
        assertEquals(texts(new BtLexer(new ANTLRStringStream(TEXT))), contentAssist);
    }

    @Test
    public void nodesModelTokenTypeIsTheContentAssistGrammars() {
        BtContentAssistLexer lexer = new BtContentAssistLexer(new ANTLRStringStream("<TreeNodesModel/>"));
        assertEquals(InternalBtLexer.RULE_NODES_MODEL, lexer.nextToken().getType());
    }

    private static List<String> texts(org.antlr.runtime.Lexer lexer) {
        List<String> result = new ArrayList<>();
        for (Token token = lexer.nextToken(); token.getType() != Token.EOF; token = lexer.nextToken()) {
            result.add(token.getText());
        }
        return result;
    }
}
