package org.emini.architecture;

import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import org.junit.jupiter.api.Test;

/**
 * The engine's packages form the pipeline the README draws: math → shape → collision → dynamics →
 * constraint, event, particle → world → io, with internal helpers usable from everywhere. A class
 * that reaches up the pipeline (a body that knows the World, an event the solver calls) fails here.
 */
class PackagePipelineTest {
    private static final JavaClasses ENGINE = new ClassFileImporter()
        .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
        .importPackages("org.emini");

    @Test
    void packagesHaveNoCycles() {
        slices().matching("org.emini.(*)..").should().beFreeOfCycles().check(ENGINE);
    }

    @Test
    void eachPackageUsesOnlyThoseBelowIt() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
            .layer("math").definedBy("org.emini.math..")
            .layer("internal").definedBy("org.emini.internal..")
            .layer("shape").definedBy("org.emini.shape..")
            .layer("collision").definedBy("org.emini.collision..")
            .layer("dynamics").definedBy("org.emini.dynamics..")
            .layer("constraint").definedBy("org.emini.constraint..")
            .layer("event").definedBy("org.emini.event..")
            .layer("particle").definedBy("org.emini.particle..")
            .layer("world").definedBy("org.emini.world..")
            .layer("io").definedBy("org.emini.io..")
            .whereLayer("io").mayNotBeAccessedByAnyLayer()
            .whereLayer("world").mayOnlyBeAccessedByLayers("io")
            .whereLayer("particle").mayOnlyBeAccessedByLayers("world", "io")
            .whereLayer("event").mayOnlyBeAccessedByLayers("world", "io")
            .whereLayer("constraint").mayOnlyBeAccessedByLayers("event", "particle", "world", "io")
            .whereLayer("dynamics").mayOnlyBeAccessedByLayers("constraint", "event", "particle", "world", "io")
            .whereLayer("collision").mayOnlyBeAccessedByLayers("dynamics", "constraint", "event", "particle", "world", "io")
            .whereLayer("shape").mayOnlyBeAccessedByLayers("collision", "dynamics", "constraint", "event", "particle", "world",
                "io")
            .whereLayer("math").mayOnlyBeAccessedByLayers("internal", "shape", "collision", "dynamics", "constraint", "event",
                "particle", "world", "io")
            .check(ENGINE);
    }
}
