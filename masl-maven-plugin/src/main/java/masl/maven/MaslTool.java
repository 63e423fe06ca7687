package masl.maven;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.apache.maven.artifact.Artifact;
import org.apache.maven.artifact.DependencyResolutionRequiredException;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.descriptor.PluginDescriptor;
import org.apache.maven.project.MavenProject;
import org.eclipse.aether.RepositorySystem;
import org.eclipse.aether.RepositorySystemSession;
import org.eclipse.aether.artifact.DefaultArtifact;
import org.eclipse.aether.collection.CollectRequest;
import org.eclipse.aether.graph.Dependency;
import org.eclipse.aether.graph.Exclusion;
import org.eclipse.aether.repository.RemoteRepository;
import org.eclipse.aether.resolution.ArtifactResult;
import org.eclipse.aether.resolution.DependencyRequest;
import org.eclipse.aether.resolution.DependencyResolutionException;

/**
 * The class path {@code masl:run} runs the {@code masl} command on: the project's runtime class path
 * (its classes, its agent classes, its dependencies) followed by {@code masl-cli} of the plug-in's
 * version and what it needs, resolved when the goal runs, from the project's repositories, and none
 * of it twice (a module the project has already comes from the project). Never the simulator
 * ({@code simexecbots}, ode4j): {@code masl:run} runs {@code .masl} programs only; JADE
 * ({@code masl-jade-bridge}) only for a run inside JADE, so a project that never runs one never
 * downloads JADE.
 */
final class MaslTool {

    static final String MAIN_CLASS = "masl.cli.Main";

    private final RepositorySystem repositories;
    private final RepositorySystemSession session;
    private final List<RemoteRepository> remotes;

    MaslTool(RepositorySystem repositories, RepositorySystemSession session, List<RemoteRepository> remotes) {
        this.repositories = repositories;
        this.session = session;
        this.remotes = remotes;
    }

    List<Path> classPath(MavenProject project, PluginDescriptor plugin, boolean inJade, List<Path> agentPath)
            throws MojoExecutionException {
        Set<Path> entries = new LinkedHashSet<>();
        Set<String> projectModules = new LinkedHashSet<>();
        try {
            project.getRuntimeClasspathElements().forEach(element -> entries.add(Path.of(element)));
        } catch (DependencyResolutionRequiredException unresolved) {
            throw new MojoExecutionException("the project's dependencies are not resolved", unresolved);
        }
        for (Artifact artifact : project.getArtifacts()) {
            projectModules.add(artifact.getGroupId() + ":" + artifact.getArtifactId());
        }
        for (ArtifactResult resolved : resolve(plugin, inJade)) {
            org.eclipse.aether.artifact.Artifact artifact = resolved.getArtifact();
            if (!projectModules.contains(artifact.getGroupId() + ":" + artifact.getArtifactId())) {
                entries.add(artifact.getFile().toPath());
            }
        }
        // The agent path is given to masl as such (--agent-path), not as class path too.
        entries.removeAll(agentPath.stream().map(Path::toAbsolutePath).toList());
        return new ArrayList<>(entries);
    }

    private List<ArtifactResult> resolve(PluginDescriptor plugin, boolean inJade) throws MojoExecutionException {
        List<Exclusion> exclusions = new ArrayList<>(List.of(new Exclusion(plugin.getGroupId(), "simexecbots", "*", "*")));
        if (!inJade) {
            exclusions.add(new Exclusion(plugin.getGroupId(), "masl-jade-bridge", "*", "*"));
        }
        Dependency cli = new Dependency(new DefaultArtifact(plugin.getGroupId(), "masl-cli", "jar", plugin.getVersion()),
                "runtime", false, exclusions);
        CollectRequest collect = new CollectRequest(cli, remotes);
        try {
            return repositories.resolveDependencies(session, new DependencyRequest(collect, null)).getArtifactResults();
        } catch (DependencyResolutionException unresolvable) {
            throw new MojoExecutionException("cannot resolve the masl command, " + plugin.getGroupId() + ":masl-cli:"
                    + plugin.getVersion() + ": " + unresolvable.getMessage(), unresolvable);
        }
    }
}
