package masl.lsp;

import java.util.List;

/** The words of MASL the editor offers, with what the language reference says of them. */
final class Vocabulary {

    /** A member usable on an entry name or a label, written as in a program. */
    record FixedMember(String name, String signature, boolean isCall, String description) {
    }

    /** MASL §6.7: usable on {@code main} and on blocks declared with {@code Entry name;}; all zero-duration. */
    static final List<FixedMember> ENTRY_MEMBERS = List.of(
            new FixedMember("count", "int count", false, "the members of the block"),
            new FixedMember("getList", "Agent[] getList()", true, "the members of the block"),
            new FixedMember("getActiveCount", "int getActiveCount()", true,
                    "members that still have an instruction of the block to run (scalar: 0 or 1)"),
            new FixedMember("getActiveList", "Agent[] getActiveList()", true,
                    "members that still have an instruction of the block to run"),
            new FixedMember("getWaitingInCount", "int getWaitingInCount()", true,
                    "members held by the entry barrier (synchronous blocks; 0 otherwise)"),
            new FixedMember("getWaitingInList", "Agent[] getWaitingInList()", true,
                    "members held by the entry barrier (synchronous blocks; empty otherwise)"),
            new FixedMember("getWaitingOutCount", "int getWaitingOutCount()", true,
                    "members held by the exit barrier (synchronous blocks; 0 otherwise)"),
            new FixedMember("getWaitingOutList", "Agent[] getWaitingOutList()", true,
                    "members held by the exit barrier (synchronous blocks; empty otherwise)"),
            new FixedMember("getLockPolicy", "String getLockPolicy()", true,
                    "\"free\" or \"locked\" for a synchronous block, \"unavailable\" otherwise"),
            new FixedMember("lock", "void lock()", true,
                    "lets waiting agents in only on release() from now on (synchronous blocks)"),
            new FixedMember("release", "void release()", true,
                    "lets every agent waiting at the entry barrier in (synchronous blocks); release(n) lets n in"));

    /** MASL §10. */
    static final List<FixedMember> LABEL_MEMBERS = List.of(
            new FixedMember("isFinished", "boolean isFinished()", true,
                    "whether every invocation registered with the label has completed"),
            new FixedMember("free", "void free()", true, "forgets the registered invocations"));

    /** MASL §8: local, implicitly declared everywhere. */
    static final List<FixedMember> SYSTEM_EVENTS = List.of(
            new FixedMember("timeout", "local event timeout", false,
                    "an invocation made by this agent was ignored by permeability, or timed out"),
            new FixedMember("uncaught_exception", "local event uncaught_exception", false,
                    "a primitive or a Java call threw; the message is the exception's class name"),
            new FixedMember("forbidden_access", "local event forbidden_access", false,
                    "a denied attribute access or limited write"));

    /** MASL §2's reserved words, and the Java type words declarations use. */
    static final List<String> KEYWORDS = List.of("import", "as", "type", "use", "newAgent", "Entry", "entry", "scalar",
            "synchronous", "asynchronous", "local", "shared", "final", "limited", "event", "LLabel", "SLabel", "react",
            "default", "resume", "restart", "reelect", "break", "exit", "emit", "emitWithMessage", "getMessageFromEvent",
            "clearEvents", "getAcceptState", "setAcceptState", "wait", "if", "else", "while", "for", "do", "loop", "new",
            "this", "null", "true", "false", "instanceof", "boolean", "byte", "char", "short", "int", "long", "float",
            "double", "String");

    /** The words that start a header (MASL §3), offered outside every block. */
    static final List<String> HEADER_KEYWORDS = List.of("import", "as", "type", "use", "newAgent", "Entry", "entry",
            "scalar", "synchronous", "asynchronous");

    private Vocabulary() {
    }
}
