package masl.jade;

import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;

/**
 * Run in a second JVM by the tests of a coordinator that dies: starts a main container on a free
 * loopback port, prints {@code port P}, and stays until its standard input closes or it is killed.
 */
public final class MainContainerMain {

    private MainContainerMain() {
    }

    public static void main(String[] args) throws Exception {
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer())) {
            System.out.println("port " + platform.port());
            System.out.flush();
            while (System.in.read() >= 0) {
                // Waits for the end of its input: the test kills this JVM before.
            }
        }
    }
}
