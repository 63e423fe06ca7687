package masl.translator.analysis;

import java.util.List;

/**
 * Entry blocks that follow each other in one statement list with no instruction between them
 * (MASL §1, §6.1); a lone block is a sequence of one. Reactions between them do not split a sequence,
 * as they are not instructions.
 */
public record ESequence(List<Block> blocks) {

    public ESequence {
        blocks = List.copyOf(blocks);
    }
}
