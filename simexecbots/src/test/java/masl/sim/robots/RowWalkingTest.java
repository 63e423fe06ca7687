package masl.sim.robots;

import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.agents.MaamAtom;
import masl.sim.physics.PhysicsWorld;
import masl.sim.xode.XodeException;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A row of atoms latched foot to foot walks with the gait of missions/row-walking.masl, driven here straight from
 * Java: all side legs back on the ground; then the odd atoms' left legs and the even atoms' right
 * legs lift, swing forward and land; then the other side legs; repeat.
 */
@Tag("slow")
class RowWalkingTest {

    private static final double SWING = 0.35;
    private static final double LIFT = 0.6;

    @ParameterizedTest
    @ValueSource(ints = {3, 6})
    void aLatchedRowWalksForwardAndStaysUpright(int n) throws XodeException {
        try (PhysicsWorld world = RobotPhysicsTest.world()) {
            SimulatedAtom.Latches latches = new SimulatedAtom.Latches();
            SimulatedAtom[] atoms = new SimulatedAtom[n];
            for (int i = 0; i < n; i++) {
                atoms[i] = SimulatedAtom.load(world, "a" + i + ".", -2 + i * 0.12, 0, 0, latches);
                latches.register(i, atoms[i]);
            }
            world.step(50);
            for (int i = 0; i + 1 < n; i++) {
                assertTrue(atoms[i].attach(MaamAtom.FRONT, i + 1, MaamAtom.BACK), "latch " + i);
            }
            world.step(50);
            double start = centreX(world, atoms);
            for (int cycle = 0; cycle < 10; cycle++) {
                for (SimulatedAtom atom : atoms) {
                    atom.setServoTarget(MaamAtom.LEFT, MaamAtom.SWING, -SWING);
                    atom.setServoTarget(MaamAtom.RIGHT, MaamAtom.SWING, -SWING);
                }
                world.step(40);
                for (int group = 0; group < 2; group++) {
                    moveGroup(atoms, group, MaamAtom.LIFT, LIFT);
                    world.step(25);
                    moveGroup(atoms, group, MaamAtom.SWING, SWING);
                    world.step(25);
                    moveGroup(atoms, group, MaamAtom.LIFT, 0);
                    world.step(25);
                }
                for (SimulatedAtom atom : atoms) {
                    double up = world.bodyPose(atom.mainBody()).worldDirection(0, 0, 1)[2];
                    assertTrue(up > 0.95, "upright in cycle " + cycle + ": " + up);
                }
            }
            double advance = centreX(world, atoms) - start;
            assertTrue(advance > 0.08, n + " atoms advanced " + advance + " m in 10 cycles");
        }
    }

    /** Group 0: odd atoms' (1-based) left legs and even atoms' right legs; group 1: the others. */
    private static void moveGroup(SimulatedAtom[] atoms, int group, int joint, double angle) {
        for (int i = 0; i < atoms.length; i++) {
            int leg = (i + group) % 2 == 0 ? MaamAtom.LEFT : MaamAtom.RIGHT;
            atoms[i].setServoTarget(leg, joint, angle);
        }
    }

    private static double centreX(PhysicsWorld world, SimulatedAtom[] atoms) {
        double sum = 0;
        for (SimulatedAtom atom : atoms) {
            sum += world.bodyPose(atom.mainBody()).x();
        }
        return sum / atoms.length;
    }
}
