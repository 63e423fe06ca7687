package masl.translator.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import masl.grammar.MASLParser;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;
import org.junit.jupiter.api.Test;

/** The model the analysis builds for the code generator. */
class ModelTest {

    private static final String PROGRAM = """
            import Default.xml;
            import robots/Khepera.xml as K;
            import robots/Explorer.xml;
            type Other use Default.xml;
            K k1, k2 = newAgent(Explorer);
            Default d = newAgent();
            Other o = newAgent(Other);
            Entry team;
            synchronous entry main (true) {
              local int a, b = 1;
              shared final double SPEED limited(K) = 0.5;
              local event bump;
              shared event go;
              LLabel l;
              SLabel s;
              react (go) { resume; }
              asynchronous entry team (true) { a = k1.getProximity(a) + team.count; }
              scalar entry report (true) { .logln("" + SPEED); }
              .nop();
              asynchronous entry last (true) { break(main); }
              react (default) { break; }
            }
            """;

    private final Analysis.Result result = Analysis.analyze(PROGRAM);
    private final AnalyzedProgram program = result.program();

    @Test
    void programIsValid() {
        result.assertNoError();
    }

    @Test
    void importedTypesByName() {
        assertEquals(List.of("Default", "K", "Explorer", "Other"), List.copyOf(program.types().keySet()));
        assertEquals("Khepera", program.types().get("K").descriptor().shortName());
        ImportedType other = program.types().get("Other");
        assertTrue(other.definedByType());
        assertSame(program.types().get("Default").descriptor(), other.descriptor());
        assertFalse(other.isSubtypeOf(program.types().get("Default")));
        assertTrue(program.types().get("Explorer").isSubtypeOf(program.types().get("K")));
    }

    @Test
    void typeMadeByTypeUseIsDistinctFromItsDescriptorsOtherNamesButASubtypeOfWhatItExtends() {
        Analysis.Result spare = Analysis.analyze("""
                import robots/Khepera.xml as K;
                import robots/Explorer.xml;
                type Spare use robots/Explorer.xml;
                K k = newAgent(Spare);
                """);
        spare.assertNoError();
        ImportedType made = spare.program().types().get("Spare");
        ImportedType explorer = spare.program().types().get("Explorer");
        assertTrue(made.isSubtypeOf(spare.program().types().get("K")));
        assertFalse(made.isSubtypeOf(explorer));
        assertFalse(explorer.isSubtypeOf(made));
        assertEquals("Spare", spare.program().agents().get(0).instantiatedType().name());
    }

    @Test
    void agentsWithTheirTypesAndProxyIds() {
        List<AgentDecl> agents = program.agents();
        assertEquals(List.of("k1", "k2", "d", "o"), agents.stream().map(AgentDecl::name).toList());
        assertEquals(List.of(0, 1, 2, 3), agents.stream().map(AgentDecl::proxyId).toList());
        assertEquals("K", agents.get(1).declaredType().name());
        assertEquals("Explorer", agents.get(1).instantiatedType().name());
        assertEquals("Default", agents.get(2).instantiatedType().name());
        assertEquals(List.of("team"), List.copyOf(program.declaredEntries()));
    }

    @Test
    void blockTreeWithESequences() {
        Block root = program.root();
        assertEquals("main", root.name());
        assertEquals(BlockMode.SYNCHRONOUS, root.mode());
        assertNull(root.parent());
        assertEquals(List.of(List.of("team", "report"), List.of("last")), root.sequences().stream()
                .map(sequence -> sequence.blocks().stream().map(Block::name).toList()).toList());
        Block report = root.children().get(1);
        assertEquals(BlockMode.SCALAR, report.mode());
        assertSame(root, report.parent());
        assertEquals(2, report.depth());
    }

    @Test
    void declarationsOfTheRoot() {
        List<Variable> variables = program.root().variables();
        assertEquals(List.of("a", "b", "SPEED"), variables.stream().map(Variable::name).toList());
        Variable a = variables.get(0);
        Variable b = variables.get(1);
        assertEquals(MaslType.INT, a.type());
        assertEquals(Sharing.LOCAL, a.sharing());
        assertSame(a.initializer(), b.initializer(), "one initialiser for every name of the declaration");
        Variable speed = variables.get(2);
        assertTrue(speed.isFinal());
        assertEquals(Sharing.SHARED, speed.sharing());
        assertEquals("K", speed.limitedTo().name());
        assertEquals(MaslType.DOUBLE, speed.type());
        assertEquals(List.of("bump:LOCAL", "go:SHARED"), program.root().events().stream()
                .map(event -> event.name() + ":" + event.sharing()).toList());
        assertEquals(List.of("l:LOCAL", "s:SHARED"), program.root().labels().stream()
                .map(label -> label.name() + ":" + label.sharing()).toList());
    }

    @Test
    void typesHaveTheirJavaSpelling() {
        assertEquals("int", MaslType.INT.javaName());
        assertEquals("java.lang.String[]", new MaslType.ArrayOf(MaslType.STRING).javaName());
        assertEquals("java.util.Map.Entry", new MaslType.JavaClass(java.util.Map.Entry.class).javaName());
        assertEquals("masl.translator.analysis.fixtures.Khepera",
                new MaslType.AgentRef(program.types().get("K")).javaName());
        assertEquals("masl.runtime.AgentImplementation", MaslType.ANY_AGENT.javaName());
    }

    @Test
    void reactionsInSourceOrder() {
        List<Reaction> reactions = program.root().reactions();
        assertEquals(2, reactions.size());
        assertEquals("go", reactions.get(0).event().name());
        assertTrue(reactions.get(1).isDefault());
    }

    @Test
    void primitiveInvocationIsBoundToEveryTypeThatHasIt() {
        MASLParser.MethodCallContext call = find(MASLParser.MethodCallContext.class, "k1.getProximity(a)");
        Member member = assertInstanceOf(Member.class, program.symbolOf(call).orElseThrow());
        assertEquals(Member.Kind.PRIMITIVE, member.kind());
        assertEquals(List.of("K", "Explorer"), member.declaringTypes().stream().map(ImportedType::name).toList());
        assertEquals(MaslType.INT, program.typeOf(call));
        AgentDecl k1 = assertInstanceOf(AgentDecl.class, program.symbolOf(call.expression()).orElseThrow());
        assertEquals(0, k1.proxyId());
        Variable a = assertInstanceOf(Variable.class,
                program.symbolOf(call.arguments().expressionList().expression(0)).orElseThrow());
        assertSame(program.root(), a.block());
    }

    @Test
    void entryMembersAndJumpTargetsAreBound() {
        MASLParser.FieldAccessContext count = find(MASLParser.FieldAccessContext.class, "team.count");
        assertEquals(Member.Kind.ENTRY_MEMBER, ((Member) program.symbolOf(count).orElseThrow()).kind());
        EntryRef team = assertInstanceOf(EntryRef.class, program.symbolOf(count.expression()).orElseThrow());
        assertSame(program.root().children().get(0), team.block());
        MASLParser.JumpTargetContext target = find(MASLParser.JumpTargetContext.class, "main");
        EntryRef main = assertInstanceOf(EntryRef.class, program.symbolOf(target.identifier()).orElseThrow());
        assertSame(program.root(), main.block());
    }

    @Test
    void expressionsHaveStaticTypes() {
        MASLParser.BinaryExprContext concatenation = find(MASLParser.BinaryExprContext.class, "\"\"+SPEED");
        assertEquals(MaslType.STRING, program.typeOf(concatenation));
        assertEquals("String", program.typeOf(concatenation).describe());
    }

    @Test
    void programWithSyntaxErrorsIsNotAnalysed() {
        Analysis.Result broken = Analysis.analyze("import Default.xml;\nasynchronous entry main (true) { foo = ; }\n");
        broken.assertError(2, 40, "unexpected ';'");
        assertNull(broken.program().root());
        assertTrue(broken.program().types().isEmpty());
    }

    @Test
    void javaMethodsAreBoundToTheReflectedMethod() throws NoSuchMethodException {
        Analysis.Result result = Analysis.analyzeBody("local double m = Math.max(1, 2.5);");
        MASLParser.MethodCallContext call =
                find(result.program(), MASLParser.MethodCallContext.class, "Math.max(1,2.5)");
        Member member = (Member) result.program().symbolOf(call).orElseThrow();
        assertEquals(Member.Kind.JAVA_METHOD, member.kind());
        assertEquals(Math.class.getMethod("max", double.class, double.class), member.javaMember());
        assertEquals(MaslType.DOUBLE, result.program().typeOf(call));
        TypeRef math = assertInstanceOf(TypeRef.class, result.program().symbolOf(call.expression()).orElseThrow());
        assertEquals(new MaslType.JavaClass(Math.class), math.type());
    }

    private <T extends ParserRuleContext> T find(Class<T> kind, String text) {
        return find(program, kind, text);
    }

    private static <T extends ParserRuleContext> T find(AnalyzedProgram analyzed, Class<T> kind, String text) {
        T found = find(analyzed.parsed().tree(), kind, text);
        assertNotNull(found, "no " + kind.getSimpleName() + " " + text);
        return found;
    }

    private static <T extends ParserRuleContext> T find(ParseTree tree, Class<T> kind, String text) {
        if (kind.isInstance(tree) && tree.getText().equals(text)) {
            return kind.cast(tree);
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            T found = find(tree.getChild(i), kind, text);
            if (found != null) {
                return found;
            }
        }
        return null;
    }
}
