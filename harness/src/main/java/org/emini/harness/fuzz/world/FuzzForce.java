package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.world.ExternalForce;
import org.emini.world.World;

/** An external force of a recipe; allocation-free, as an ExternalForce must be. */
final class FuzzForce implements ExternalForce {
    private final ForceRecipe recipe;
    private final Body body;

    FuzzForce(ForceRecipe recipe, Body body) {
        this.recipe = recipe;
        this.body = body;
    }

    @Override
    public void applyForce(World world, float timestep) {
        if (recipe.kind == ForceRecipe.Kind.wind) {
            for (int i = 0, n = world.getBodyCount(); i < n; i++) {
                Body b = world.getBody(i);
                if (b.isDynamic()) {
                    b.applyAcceleration(recipe.fx, recipe.fy);
                }
            }
            return;
        }
        if (body.getWorld() != world) {
            return;
        }
        switch (recipe.kind) {
            case force -> body.applyForce(recipe.fx, recipe.fy);
            case forceAt -> body.applyForceAt(recipe.fx, recipe.fy,
                    body.toWorldX(recipe.px, recipe.py), body.toWorldY(recipe.px, recipe.py));
            default -> body.applyTorque(recipe.torque);
        }
    }
}
