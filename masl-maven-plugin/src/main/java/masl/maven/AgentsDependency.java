package masl.maven;

import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.descriptor.PluginDescriptor;
import org.apache.maven.project.MavenProject;

/**
 * The one dependency a project that translates missions must declare: {@code org.masl:agents}, the
 * shipped agent types the project's own extend, which brings the runtime the generated Java calls.
 * A plug-in adds no dependency to a Maven project, so its absence is said before the compiler
 * plug-in would report it as hundreds of missing symbols.
 */
final class AgentsDependency {

    static final String ARTIFACT_ID = "agents";

    private AgentsDependency() {
    }

    static void require(MavenProject project, PluginDescriptor plugin) throws MojoFailureException {
        boolean declared = project.getArtifacts().stream()
                .anyMatch(artifact -> artifact.getGroupId().equals(plugin.getGroupId()) && artifact.getArtifactId().equals(ARTIFACT_ID)
                        && artifact.getArtifactHandler().isAddedToClasspath() && !"test".equals(artifact.getScope()));
        if (!declared) {
            throw new MojoFailureException("the missions' Java compiles against " + plugin.getGroupId() + ":" + ARTIFACT_ID
                    + ", which is not among the project's compile dependencies; add to the pom's <dependencies>:\n"
                    + "    <dependency>\n"
                    + "      <groupId>" + plugin.getGroupId() + "</groupId>\n"
                    + "      <artifactId>" + ARTIFACT_ID + "</artifactId>\n"
                    + "      <version>" + plugin.getVersion() + "</version>\n"
                    + "    </dependency>");
        }
    }
}
