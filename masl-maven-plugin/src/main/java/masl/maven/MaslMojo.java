package masl.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.descriptor.PluginDescriptor;
import org.apache.maven.project.MavenProject;

/**
 * What every goal of the plug-in reads of a project: the project itself, the plug-in's coordinates
 * and the agent path, the folders and jars of agent types kept outside the project. Maven sets these
 * fields from the plug-in's descriptor ({@code META-INF/maven/plugin.xml}).
 */
abstract class MaslMojo extends AbstractMojo {

    private MavenProject project;
    private PluginDescriptor plugin;
    private File[] agentPath;

    MavenProject project() {
        return project;
    }

    /** This plug-in's group and version, which are those of the MASL modules it works with. */
    PluginDescriptor plugin() {
        return plugin;
    }

    /** The agent path's entries, searched after a program's folder and before the shipped descriptors. */
    List<Path> agentPath() {
        return agentPath == null ? List.of() : Arrays.stream(agentPath).map(File::toPath).toList();
    }

    /** {@code file} as a user in a shell in the project's folder names it, as masl's diagnostics do. */
    String relative(Path file) {
        return project.getBasedir().toPath().relativize(file.toAbsolutePath()).toString();
    }
}
