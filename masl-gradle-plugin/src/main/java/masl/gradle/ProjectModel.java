package masl.gradle;

import java.io.File;
import org.gradle.api.Project;
import org.gradle.api.tasks.SourceSetContainer;

/**
 * What the plug-in reads of a project, found the same way from Gradle 4.4 to current Gradle: the
 * source sets are a convention property up to 7.0 and an extension from 7.1 (the convention is gone
 * since 9), the build folder a {@code ProjectLayout} property ({@code getBuildDir()} is deprecated).
 */
final class ProjectModel {

    private ProjectModel() {
    }

    static SourceSetContainer sourceSets(Project project) {
        Object extension = project.getExtensions().findByName("sourceSets");
        return (SourceSetContainer) (extension != null ? extension : project.property("sourceSets"));
    }

    static File buildDir(Project project, String path) {
        return new File(project.getLayout().getBuildDirectory().get().getAsFile(), path);
    }

    /** {@code file} relative to {@code folder}, as a user in a shell there names it. */
    static String relative(File folder, File file) {
        return folder.toPath().relativize(file.toPath()).toString();
    }
}
