package masl.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.apache.maven.model.Resource;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;

/**
 * {@code masl:compile}, in {@code generate-sources}: translates the missions of {@code src/main/masl}
 * into Java under {@code target/generated-sources/masl} (package {@code masl.generated.<program>}),
 * a source root the compiler plug-in then compiles with the project's own Java. The descriptors of
 * {@code src/main/masl} become resources, so that they travel in the jar next to the classes they
 * describe and the jar can be another project's agent path.
 */
public class CompileMojo extends ProgramsMojo {

    private File outputDirectory;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        Path programsDir = sourceDirectory().toPath();
        addDescriptorsAsResources();
        List<Path> programs = Programs.in(programsDir);
        Path output = outputDirectory.toPath();
        GeneratedSources generated = new GeneratedSources(output);
        if (programs.isEmpty()) {
            generated.update(Map.of());
            getLog().info("No MASL programs in " + relative(programsDir));
            return;
        }
        AgentsDependency.require(project(), plugin());
        generated.update(new ProjectTranslation(this, scope()).translate(programs));
        scope().addSourceRoot(project(), output.toString());
        getLog().info("Translated " + programs.size() + " MASL program" + (programs.size() == 1 ? "" : "s")
                + " of " + relative(programsDir) + " into " + relative(output));
    }

    /** The main code's missions; {@link TestCompileMojo} translates the tests'. */
    SourceScope scope() {
        return SourceScope.MAIN;
    }

    /** Once: a lifecycle forked by masl:run runs this goal again on the same project. */
    private void addDescriptorsAsResources() {
        String folder = sourceDirectory().getPath();
        if (scope().resources(project()).stream().anyMatch(resource -> folder.equals(resource.getDirectory()))) {
            return;
        }
        Resource descriptors = new Resource();
        descriptors.setDirectory(folder);
        descriptors.addInclude("**/*.xml");
        scope().addResource(project(), descriptors);
    }
}
