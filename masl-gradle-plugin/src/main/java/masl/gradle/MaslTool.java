package masl.gradle;

import java.util.Map;
import java.util.function.BooleanSupplier;
import org.gradle.api.Project;
import org.gradle.api.artifacts.Configuration;
import org.gradle.api.artifacts.ModuleDependency;
import org.gradle.api.attributes.Attribute;
import org.gradle.api.attributes.AttributeContainer;
import org.gradle.api.plugins.JavaPlugin;

/**
 * The configurations {@code maslTool} and {@code maslContainerTool}: what {@code maslRun} and
 * {@code maslContainer} run, the {@code masl} command ({@code masl-cli}) with the project's runtime
 * dependencies, resolved together so that no module appears twice. Only a run inside JADE, and a
 * container, bring {@code masl-jade-bridge} and JADE; the simulator ({@code simexecbots}, ode4j)
 * never comes, the tasks running {@code .masl} programs only. Nothing is resolved unless its task runs.
 */
final class MaslTool {

    private MaslTool() {
    }

    /** The configuration {@code name}, the masl command {@code task} runs: with JADE if {@code inJade} says so when resolved. */
    static Configuration create(Project project, MaslArtifacts artifacts, String name, String task, BooleanSupplier inJade) {
        Configuration runtime = project.getConfigurations().getByName(JavaPlugin.RUNTIME_CLASSPATH_CONFIGURATION_NAME);
        Configuration tool = project.getConfigurations().create(name);
        tool.setDescription("The masl command " + task + " runs, with the project's runtime dependencies");
        tool.setCanBeConsumed(false);
        runtime.getExtendsFrom().forEach(tool::extendsFrom);
        AttributeContainer attributes = runtime.getAttributes();
        attributes.keySet().forEach(key -> copy(key, attributes, tool.getAttributes()));
        tool.withDependencies(dependencies -> {
            ModuleDependency cli = (ModuleDependency) project.getDependencies().create(artifacts.module("masl-cli"));
            cli.exclude(Map.of("group", artifacts.group(), "module", "simexecbots"));
            if (!inJade.getAsBoolean()) {
                cli.exclude(Map.of("group", artifacts.group(), "module", "masl-jade-bridge"));
            }
            dependencies.add(cli);
        });
        return tool;
    }

    private static <T> void copy(Attribute<T> key, AttributeContainer from, AttributeContainer to) {
        to.attribute(key, from.getAttribute(key));
    }
}
