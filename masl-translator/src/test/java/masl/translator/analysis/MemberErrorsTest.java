package masl.translator.analysis;

import static masl.translator.analysis.Analysis.analyzeBody;

import org.junit.jupiter.api.Test;

/** Members of agents, entries, labels and Java objects that do not exist or do not fit (MASL §4, §6.7, §9, §10). */
class MemberErrorsTest {

    @Test
    void primitiveNoImportedTypeHasIsReported() {
        analyzeBody(".fly();").assertError(7, 2, "cannot find primitive fly in any imported agent type");
    }

    @Test
    void attributeNoImportedTypeHasIsReported() {
        analyzeBody("k.speed = 1;").assertError(7, 3, "cannot find attribute speed in any imported agent type");
    }

    @Test
    void memberOfSomeImportedTypeIsFineOnAnyAgent() {
        analyzeBody("d.getProximity(1);\n.startGripper();\nd.battery = 3;\n.logln(.explore(\"north\"));")
                .assertNoError();
    }

    @Test
    void primitiveWithTooFewArgumentsIsReported() {
        analyzeBody("local int p = .getProximity();")
                .assertError(7, 16, "primitive int getProximity(int) takes 1 argument, found 0");
    }

    @Test
    void primitiveWithAnArgumentOfTheWrongTypeIsReported() {
        analyzeBody("k.setSpeeds(1, \"fast\");")
                .assertError(7, 16,
                        "argument 2 of primitive void setSpeeds(double, double) must be double, found String");
    }

    @Test
    void anythingPassesForAStringParameter() {
        analyzeBody(".logln(3 > 2);\n.log(k);\n.logln(null);").assertNoError();
    }

    @Test
    void finalAttributeCannotBeAssigned() {
        analyzeBody(".MAX_SPEED = 1.0;").assertError(7, 2, "cannot assign a value to final attribute MAX_SPEED");
    }

    @Test
    void anAgentsOwnAttributeIsNotReadOrWrittenThroughItsType() {
        analyzeBody("local int b = Khepera.battery;").assertError(7, 23, "battery is not a static attribute of Khepera:"
                + " each agent has its own, used on an agent of that type (a.battery, or .battery for the current agent's)");
        analyzeBody("Khepera.battery = 3;").assertError(7, 9, "battery is not a static attribute of Khepera:"
                + " each agent has its own, used on an agent of that type (a.battery, or .battery for the current agent's)");
    }

    @Test
    void aStaticAttributeIsReadThroughItsType() {
        analyzeBody("local double top = Khepera.MAX_SPEED;\nlocal int own = k.battery;").assertNoError();
    }

    @Test
    void unknownMethodOnAStringIsReported() {
        analyzeBody("local String s = \"abc\";\n.logln(s.substrin(1));")
                .assertError(8, 10, "cannot find method substrin(int) in String");
    }

    @Test
    void methodWithArgumentsThatFitNoOverloadIsReported() {
        analyzeBody("local String s = \"abc\";\n.logln(s.substring(true));")
                .assertError(8, 10, "no method String.substring accepts (boolean)");
    }

    @Test
    void anyMethodOnAnObjectIsResolvedAtRunTime() {
        analyzeBody("""
                local java.util.Vector v = new java.util.Vector();
                local int n = 0;
                .logln(v.get(0).whatever(1));
                n = v.get(0);""").assertNoError();
    }

    @Test
    void methodsOfUtilityAndLibraryClassesAreFound() {
        analyzeBody("""
                local Vector2d p = .position();
                local double dist = Math.max(p.length(), p.x) + Integer.MAX_VALUE;
                local java.util.List<String> names = new ArrayList<String>();
                Thread.sleep(10);
                .logln(String.format("%d %s", 1, names.size()) + String.class + Collections.emptyList());""")
                .assertNoError();
    }

    @Test
    void unknownStaticMethodIsReported() {
        analyzeBody("local int m = Math.maximum(1, 2);")
                .assertError(7, 20, "cannot find method maximum(int, int) in class Math");
    }

    @Test
    void unknownEntryMemberIsReported() {
        analyzeBody(".logln(main.size);").assertError(7, 13, "entry main has no member size; entry members are count, "
                + "getList(), getActiveCount(), getActiveList(), getWaitingInCount(), getWaitingInList(), "
                + "getWaitingOutCount(), getWaitingOutList(), getLockPolicy(), lock(), release() and release(n)");
    }

    @Test
    void entryMethodWrittenWithoutParenthesesIsReported() {
        analyzeBody("local int n = main.getActiveCount;")
                .assertError(7, 20, "getActiveCount is a method: write main.getActiveCount()");
    }

    @Test
    void entryListsHoldAgents() {
        analyzeBody("local Khepera[] team = main.getList();\nmain.release(2);\nteam[0].startGripper();")
                .assertNoError();
    }

    @Test
    void undeclaredNameIsReported() {
        analyzeBody("foo = 1;").assertError(7, 1, "cannot find symbol foo");
    }

    @Test
    void unknownTypeInADeclarationIsReported() {
        analyzeBody("local Foo f;").assertError(7, 7, "cannot find type Foo");
    }

    @Test
    void limitedToAnUnknownTypeIsReported() {
        analyzeBody("shared int r limited(Robo) = 0;")
                .assertError(7, 22, "cannot find agent type Robo in limited(Robo)");
    }

    @Test
    void labelAssignmentMustStoreIntoAVariableInScope() {
        analyzeBody("LLabel l;\nl.y = .getProximity(1);")
                .assertError(8, 3, "in l.y = …, y must be a variable in scope");
    }

    @Test
    void labelLaunchMustTargetAnAgentOrThis() {
        analyzeBody("LLabel l;\nlocal int z;\nl.z.startGripper();")
                .assertError(9, 3, "in l.z.…, z must be an agent or this");
    }

    @Test
    void isFinishedNeedsALabel() {
        analyzeBody("local int x;\nif (isFinished(x)) .nop();").assertError(8, 16, "isFinished needs a label, found x");
    }

    @Test
    void labelAssignmentStoresTheResultOfAnInvocation() {
        analyzeBody("LLabel l;\nlocal int x;\nl.x = 3;")
                .assertError(9, 7,
                        "a label assignment stores the result of a primitive invocation, such as .m(…) or a.m(…)");
    }

    @Test
    void labelFormsAreFine() {
        analyzeBody("""
                LLabel l;
                local int x;
                local Khepera member = main.getList()[0];
                l.member.startGripper();
                l.k.startGripper();
                l.this.startGripper();
                l.startGripper();
                l.x = k.getProximity(3);
                l.k.battery = .getProximity(2);
                l.this.battery = this.getProximity(1);
                x = l.getRemainingInvocations();
                if (l.isFinished() || isFinished(l)) l.free();""").assertNoError();
    }
}
