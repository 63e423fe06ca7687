package masl.gradle;

import org.gradle.api.Project;
import org.gradle.api.file.ConfigurableFileCollection;

/**
 * The {@code masl { }} block of a build script. {@code agentPath} lists the folders and jars that
 * hold agent type descriptors and their implementation classes (components.md, "Agent path"); the
 * descriptors shipped with MASL are always found after them, and so are descriptors next to a program.
 */
public class MaslExtension {

    private final ConfigurableFileCollection agentPath;

    public MaslExtension(Project project) {
        this.agentPath = project.files();
    }

    public ConfigurableFileCollection getAgentPath() {
        return agentPath;
    }

    /** Adds folders or jars (anything {@code project.files} accepts) to the agent path. */
    public void agentPath(Object... entries) {
        agentPath.from(entries);
    }

    public void setAgentPath(Object entries) {
        agentPath.setFrom(entries);
    }
}
