package masl.maven;

import java.nio.file.Path;
import java.util.List;
import org.apache.maven.artifact.DependencyResolutionRequiredException;
import org.apache.maven.model.Resource;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.project.MavenProject;

/**
 * The half of a project a goal works on: the main code ({@code src/main/masl} beside
 * {@code src/main/java}) or the tests' ({@code src/test/masl} beside {@code src/test/java}, with the
 * main classes already compiled on their class path). Each has its Java source roots, class path,
 * generated source root and resources, which Maven keeps apart.
 */
enum SourceScope {

    MAIN("agent-classes") {
        @Override
        List<String> javaSourceRoots(MavenProject project) {
            return project.getCompileSourceRoots();
        }

        @Override
        List<String> classPathElements(MavenProject project) throws DependencyResolutionRequiredException {
            return project.getCompileClasspathElements();
        }

        @Override
        String outputDirectory(MavenProject project) {
            return project.getBuild().getOutputDirectory();
        }

        @Override
        void addSourceRoot(MavenProject project, String root) {
            project.addCompileSourceRoot(root);
        }

        @Override
        List<Resource> resources(MavenProject project) {
            return project.getResources();
        }

        @Override
        void addResource(MavenProject project, Resource resource) {
            project.addResource(resource);
        }
    },

    TEST("test-agent-classes") {
        @Override
        List<String> javaSourceRoots(MavenProject project) {
            return project.getTestCompileSourceRoots();
        }

        @Override
        List<String> classPathElements(MavenProject project) throws DependencyResolutionRequiredException {
            return project.getTestClasspathElements();
        }

        @Override
        String outputDirectory(MavenProject project) {
            return project.getBuild().getTestOutputDirectory();
        }

        @Override
        void addSourceRoot(MavenProject project, String root) {
            project.addTestCompileSourceRoot(root);
        }

        @Override
        List<Resource> resources(MavenProject project) {
            return project.getTestResources();
        }

        @Override
        void addResource(MavenProject project, Resource resource) {
            project.addTestResource(resource);
        }
    };

    private final String agentClassesFolder;

    SourceScope(String agentClassesFolder) {
        this.agentClassesFolder = agentClassesFolder;
    }

    abstract List<String> javaSourceRoots(MavenProject project);

    abstract List<String> classPathElements(MavenProject project) throws DependencyResolutionRequiredException;

    /** Where the compiler plug-in puts this half's classes. */
    abstract String outputDirectory(MavenProject project);

    abstract void addSourceRoot(MavenProject project, String root);

    abstract List<Resource> resources(MavenProject project);

    abstract void addResource(MavenProject project, Resource resource);

    /** The plug-in's own folder for this half's Java, compiled before its missions are translated. */
    Path agentClasses(MavenProject project) {
        return Path.of(project.getBuild().getDirectory(), "masl", agentClassesFolder);
    }

    /**
     * The class path without this half's own output folder, whose classes may be those of an earlier
     * build: the agent classes compiled just now stand for them.
     */
    List<Path> classPath(MavenProject project) throws MojoExecutionException {
        try {
            Path output = Path.of(outputDirectory(project));
            return classPathElements(project).stream().map(Path::of).filter(entry -> !entry.equals(output)).toList();
        } catch (DependencyResolutionRequiredException unresolved) {
            throw new MojoExecutionException("the project's dependencies are not resolved", unresolved);
        }
    }
}
