package masl.maven;

import java.io.File;

/**
 * A goal that works on the missions of a project: where they and their descriptors are
 * ({@code src/main/masl}), besides what every goal reads ({@link MaslMojo}).
 */
abstract class ProgramsMojo extends MaslMojo {

    private File sourceDirectory;

    File sourceDirectory() {
        return sourceDirectory;
    }
}
