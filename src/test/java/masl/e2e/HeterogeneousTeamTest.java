package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import masl.runtime.descriptor.AgentPath;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import org.junit.jupiter.api.Test;

/**
 * Heterogeneous teams (MASL §4) from MASL source to journal, on the shipped soft robots: one program,
 * specialised per agent type; subtypes, their redefinitions, members some types lack, types made by
 * {@code type T use F}, utility classes.
 */
class HeterogeneousTeamTest {

    @Test
    void theSubtypesRedefinitionRunsAndTheMemberItsSupertypeLacksIsANop() {
        MaslMission team = MaslMission.fromString("team.masl", """
                import SoftWheeledRobot.xml as Soft;
                import Scout.xml as Scout;
                Soft rover = newAgent(Soft);
                Scout scout = newAgent(Scout);
                synchronous entry main (true) {
                    local double moved = .moveForward(20);
                    .logln(.getProxyID() + " moved " + moved);
                    .logln(.getProxyID() + " scans " + .scan());
                    .logln(.getProxyID() + " battery " + .getBattery());
                }
                """);
        // The scout's moveForward (Scout.xml's redefinition) stops short of the wall; the rover bumps
        // into it. The rover has no scan: that statement is a nop() for it, which still takes its
        // instruction, so in lock-step its battery line never comes before the scout's scan line.
        team.run().assertLinesInAnyOrder("0 moved 5.0", "1 moved 4.5", "1 scans 0.5", "0 battery 0.95", "1 battery 0.95");
        team.explore(100).assertEveryRun(run -> run.assertEveryBefore("1 scans .*", "\\d battery .*"));
    }

    @Test
    void aProgramWrittenForRobotsRunsOnEveryRobotTypeWithItsUtilityClass() {
        MaslMission team = MaslMission.fromString("robots.masl", """
                import Robot.xml as Robot;
                import SoftWheeledRobot.xml as Soft;
                import Scout.xml as Scout;
                Robot still = newAgent(Robot);
                Robot rover = newAgent(Soft);
                Robot scout = newAgent(Scout);
                asynchronous entry main (true) {
                    local Position home = new Position(0, 0);
                    .turnLeft(90);
                    .moveForward(3);
                    .logln(.getProxyID() + " at " + .getPosition() + ", " + .getPosition().distanceTo(home) + " m from home");
                    asynchronous entry spent (.getBattery() < 1) {
                        .logln(.getProxyID() + " used its battery");
                    }
                }
                """);
        team.run().assertLinesInAnyOrder("0 at (0.0, 0.0), 0.0 m from home", "1 at (0.0, 3.0), 3.0 m from home",
                "2 at (0.0, 3.0), 3.0 m from home", "1 used its battery", "2 used its battery");
    }

    @Test
    void testsAndConditionsOnAnAbsentMemberAreFalseAndItsInitialiserGivesTheDefault() {
        MaslMission team = MaslMission.fromString("absent.masl", """
                import SoftWheeledRobot.xml as Soft;
                import Scout.xml as Scout;
                Soft rover = newAgent(Soft);
                Scout scout = newAgent(Scout);
                asynchronous entry main (true) {
                    local double range = .scan();
                    .logln(.getProxyID() + " range " + range);
                    asynchronous entry scouting (.scan() > 0) {
                        .logln(.getProxyID() + " scouts");
                    }
                    while (.scan() > 2) {
                        .moveForward(1);
                    }
                    .logln(.getProxyID() + " stopped at " + .getX());
                }
                """);
        team.run().assertLinesInAnyOrder("0 range 0.0", "1 range 5.0", "1 scouts", "0 stopped at 0.0", "1 stopped at 3.0");
    }

    @Test
    void aTypeMadeByTypeUseIsDistinctForLimitedAndTypeTestsAndStillARobot() {
        MaslMission team = MaslMission.fromString("spare.masl", """
                import Robot.xml as Robot;
                import SoftWheeledRobot.xml as Soft;
                type Spare use SoftWheeledRobot.xml;
                Robot rover = newAgent(Soft);
                Spare spare = newAgent(Spare);
                Robot other = newAgent(Spare);
                synchronous entry main (true) {
                    shared int written limited(Spare) = 0;
                    local int i, spares = 0;
                    local Robot[] all;
                    react (forbidden_access) {
                        .logln(.getProxyID() + " may not write " + getMessageFromEvent(forbidden_access));
                        resume;
                    }
                    written++;
                    all = main.getList();
                    for (i = 0; i < all.length; i++) {
                        if (all[i] instanceof Spare) {
                            spares++;
                        }
                    }
                    .logln(.getProxyID() + ": Soft " + (this instanceof Soft) + ", Spare " + (this instanceof Spare)
                            + ", Robot " + (this instanceof Robot) + ", sees " + spares + " spares");
                    scalar entry report (true) {
                        .logln("written " + written);
                    }
                }
                """);
        MissionRun run = team.run();
        run.assertLinesInAnyOrder("0 may not write written", "0: Soft true, Spare false, Robot true, sees 2 spares",
                "1: Soft false, Spare true, Robot true, sees 2 spares", "2: Soft false, Spare true, Robot true, sees 2 spares",
                "written 2");
    }

    @Test
    void aNamedAgentIsInvokedAsTheTypeItWasCreatedWithAndWhatItLacksGivesTheDefault() {
        MaslMission team = MaslMission.fromString("named.masl", """
                import Robot.xml as Robot;
                import SoftWheeledRobot.xml as Soft;
                import Scout.xml as Scout;
                Soft rover = newAgent(Soft);
                Robot scout = newAgent(Scout);
                asynchronous entry main (true) {
                    local double d = 7;
                    scalar entry ask (true) {
                        d = scout.scan();
                        .logln("scout scans " + d + ", keeps " + scout.SAFETY_MARGIN + " m");
                        d = rover.scan();
                        .logln("rover scans " + d);
                        scout.moveForward(10);
                        rover.moveForward(10);
                        .logln("scout at " + scout.getX() + ", rover at " + rover.getX());
                    }
                }
                """);
        team.run().assertJournal("scout scans 5.0, keeps 0.5 m\nrover scans 0.0\nscout at 4.5, rover at 5.0\n");
    }

    @Test
    void aDegradedRobotDrivesItselfAndIsStoppedByOthersAndADeadOneDoesNotMove() {
        // Robot.xml and SoftWheeledRobot.xml: in "degraded" others may read and stop it, not move it;
        // in "dead" it may not move itself either. A refused invocation raises timeout (MASL 11).
        MaslMission degraded = MaslMission.fromString("degraded.masl", """
                import SoftWheeledRobot.xml as Rover;
                Rover tired, helper = newAgent(Rover);
                synchronous entry main (true) {
                    local int refused = 0;
                    react (timeout) {
                        refused++;
                        .logln(.getProxyID() + " refused: " + getMessageFromEvent(timeout));
                        resume;
                    }
                    scalar entry drain (true) {
                        while (tired.getBattery() >= 0.5) { tired.moveForward(0.2); }
                    }
                    .nop(); // one e-sequence of blocks would let tired go on while helper drains it (MASL 6.1)
                    asynchronous entry tiredRobot (.getProxyID() == 0) {
                        setAcceptState("degraded");
                        .moveForward(1);
                        .logln("degraded, drove itself to " + .getX());
                    }
                    .nop();
                    asynchronous entry helperRobot (.getProxyID() == 1) {
                        tired.moveForward(1);
                        tired.stop();
                        .logln("helper sees " + tired.getX() + " battery " + tired.getBattery() + " state " + getAcceptState(tired));
                    }
                    .nop();
                    asynchronous entry deadRobot (.getProxyID() == 0) {
                        setAcceptState("dead");
                        .moveForward(1);
                        .logln("dead at " + .getX() + ", refused " + refused);
                    }
                }
                """);
        String journal = """
                degraded, drove itself to 3.2
                1 refused: moveForward
                helper sees 3.2 battery 0.4 state degraded
                0 refused: moveForward
                dead at 3.2, refused 1
                """;
        degraded.run().assertJournal(journal);
        degraded.explore(30).assertEveryRun(run -> run.assertJournal(journal));
    }

    @Test
    void aTypesConstantsAreReadThroughTheTypeByAnyAgent() {
        MaslMission constants = MaslMission.fromString("constants.masl", """
                import Robot.xml as Robot;
                import SoftWheeledRobot.xml as Soft;
                import Scout.xml as Scout;
                Robot still = newAgent(Robot);
                Soft scout = newAgent(Scout);
                asynchronous entry main (true) {
                    .logln(.getProxyID() + ": a move costs " + Soft.MOVE_COST + " %, a scout keeps " + Scout.SAFETY_MARGIN + " m");
                }
                """);
        constants.run().assertLinesInAnyOrder("0: a move costs 5 %, a scout keeps 0.5 m", "1: a move costs 5 %, a scout keeps 0.5 m");
        Translation other = new Translator(AgentPath.parse("")).translate(new SourceFile("static.masl", Path.of("src/test/resources"), """
                import workers/Worker.xml;
                Worker w = newAgent(Worker);
                asynchronous entry main (true) {
                    .logln(Worker.made);
                }
                """));
        assertEquals(List.of("4:12: a static attribute read through its type, unless a constant, is not supported yet by the translator"),
                other.diagnostics().sorted().stream().map(d -> d.line() + ":" + d.column() + ": " + d.message()).toList());
    }

    @Test
    void anEmptyBatteryStopsARobotWithAnUncaughtException() {
        MaslMission drain = MaslMission.fromString("drain.masl", """
                import SoftWheeledRobot.xml as Soft;
                Soft rover = newAgent(Soft);
                asynchronous entry main (true) {
                    local int moves = 0;
                    react (uncaught_exception) {
                        .logln(getMessageFromEvent(uncaught_exception) + " after " + moves + " moves, at " + .getPosition());
                        break;
                    }
                    do {
                        .moveForward(1);
                        moves++;
                    } loop
                }
                """);
        drain.run().assertJournal("masl.agents.BatteryEmptyException after 20 moves, at (5.0, 0.0)\n");
    }

    @Test
    void theMixedTeamMissionReportsTheSameUnderEverySchedule() {
        MaslMission mixed = MaslMission.fromFile(Path.of("missions/mixed-team.masl"));
        String journal = """
                rover 0: 3 laps, 60.0 m, ended at (0.0, 0.0), battery 0.18
                rover 1: 3 laps, 60.0 m, ended at (0.0, 0.0), battery 0.18
                scout 2: 3 laps, 59.0 m, ended at (-0.5, -0.5), closest wall 0.5 m, battery 0.18
                """;
        mixed.run().assertJournal(journal);
        mixed.explore(50).assertEveryRun(run -> run.assertJournal(journal));
    }
}
