package masl.maven;

import java.nio.file.Path;
import java.util.List;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;

/**
 * {@code masl:check}: reports every error that {@code masl:compile} would, in the programs of
 * {@code src/main/masl}, their descriptors and the agent classes these name, and writes nothing but
 * the agent classes it checks against. Bound to no phase: a goal to type, as {@code masl check} is a
 * command to type.
 */
public class CheckMojo extends ProgramsMojo {

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        Path programsDir = sourceDirectory().toPath();
        List<Path> programs = Programs.in(programsDir);
        if (programs.isEmpty()) {
            getLog().info("No MASL programs in " + relative(programsDir));
            return;
        }
        new ProjectTranslation(this, SourceScope.MAIN).translate(programs);
        getLog().info("No errors in the " + programs.size() + " MASL program" + (programs.size() == 1 ? "" : "s")
                + " of " + relative(programsDir));
    }
}
