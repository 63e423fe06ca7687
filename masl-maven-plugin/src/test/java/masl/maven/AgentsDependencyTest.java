package masl.maven;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.apache.maven.artifact.Artifact;
import org.apache.maven.artifact.DefaultArtifact;
import org.apache.maven.artifact.handler.DefaultArtifactHandler;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.descriptor.PluginDescriptor;
import org.apache.maven.project.MavenProject;
import org.junit.jupiter.api.Test;

/** A project that translates missions without org.masl:agents among its compile dependencies is told what to add. */
class AgentsDependencyTest {

    private final PluginDescriptor plugin = plugin();

    @Test
    void aProjectWithoutTheAgentsIsToldTheDependencyToDeclare() {
        MojoFailureException missing = assertThrows(MojoFailureException.class,
                () -> AgentsDependency.require(project(artifact("masl-testing", Artifact.SCOPE_COMPILE)), plugin));

        assertTrue(missing.getMessage().contains("\n    <dependency>\n      <groupId>org.masl</groupId>\n"
                + "      <artifactId>agents</artifactId>\n      <version>0.3.0</version>\n    </dependency>"), missing.getMessage());
    }

    @Test
    void theAgentsForTheTestsOnlyAreNotEnough() {
        assertThrows(MojoFailureException.class, () -> AgentsDependency.require(project(artifact("agents", Artifact.SCOPE_TEST)), plugin));
    }

    @Test
    void theAgentsAmongTheCompileDependenciesAreEnough() {
        assertDoesNotThrow(() -> AgentsDependency.require(project(artifact("agents", Artifact.SCOPE_COMPILE)), plugin));
    }

    private static PluginDescriptor plugin() {
        PluginDescriptor plugin = new PluginDescriptor();
        plugin.setGroupId("org.masl");
        plugin.setArtifactId("masl-maven-plugin");
        plugin.setVersion("0.3.0");
        return plugin;
    }

    private static Artifact artifact(String name, String scope) {
        DefaultArtifactHandler jar = new DefaultArtifactHandler("jar");
        jar.setAddedToClasspath(true);
        return new DefaultArtifact("org.masl", name, "0.3.0", scope, "jar", null, jar);
    }

    private static MavenProject project(Artifact artifact) {
        MavenProject project = new MavenProject();
        project.setArtifacts(Set.of(artifact));
        return project;
    }
}
