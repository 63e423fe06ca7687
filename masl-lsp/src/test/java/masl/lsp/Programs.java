package masl.lsp;

/** The programs the editor tests type into. */
final class Programs {

    /**
     * Two agent types (one with attributes, an asynchronous primitive and permeability states), nested blocks
     * with variables, events and a label, a sibling block whose names are out of scope, a reaction.
     * {@code /*HERE*}{@code /} stands where a test types.
     */
    static final String TEAM = """
            import Default.xml as Default;
            import SoftWheeledRobot.xml as Rover;
            Default leader = newAgent(Default);
            Rover r1, r2 = newAgent(Rover);
            Entry work;
            asynchronous entry main (true) {
              shared int total = 0;
              shared event go;
              SLabel calls;
              asynchronous entry work (.getProxyID() > 0) {
                local double distance = 1.5;
                local event done;
                synchronous entry inner (total < 3) {
                  local int steps = 0;
                  /*HERE*/
                }
              }
              scalar entry other (true) {
                local int hidden = 0;
              }
              react (go) {
                resume;
              }
            }
            """;

    private Programs() {
    }

    /** {@link #TEAM} with {@code typed} where the test types. */
    static String team(String typed) {
        return TEAM.replace("/*HERE*/", typed);
    }
}
