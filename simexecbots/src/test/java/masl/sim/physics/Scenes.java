package masl.sim.physics;

import masl.sim.xode.XodeSource;

/** Small scenes shared by the physics tests. */
final class Scenes {

    /** A ground plane z = 0. */
    static final XodeSource GROUND = XodeSource.text("ground.xode",
            "<xode version=\"1.0r23\"><world><space><geom name=\"floor\"><plane a=\"0\" b=\"0\" c=\"1\" d=\"0\"/></geom>"
            + "</space></world></xode>");

    static final XodeSource KHEPERA = XodeSource.resource("masl/agents/robots/wheeled-robot.xode");
    static final XodeSource MAAM_ATOM = XodeSource.resource("masl/agents/robots/maam-atom.xode");

    /** The pendulum of xode.md §2, Y up. */
    static final XodeSource PENDULUM = XodeSource.text("pendulum.xode", """
            <xode version="1.0r23" name="pendulum">
             <world><space>
              <body name="bob">
               <transform><position x="0" y="2" z="0"/></transform>
               <mass><mass_shape density="500"><sphere radius="0.1"/></mass_shape></mass>
               <geom><sphere radius="0.1"/></geom>
               <joint name="pivot"><hinge>
                 <anchor x="0" y="3" z="0"/>
                 <axis x="0" y="0" z="1" LowStop="-1.2" HiStop="1.2"/>
               </hinge></joint>
              </body>
              <geom name="floor"><plane a="0" b="1" c="0" d="0"/></geom>
             </space></world>
            </xode>""");

    private Scenes() {
    }

    /** Lock-step defaults with real-time pacing off. */
    static PhysicsSettings settings() {
        return PhysicsSettings.defaults().withRealTimeFactor(0);
    }
}
