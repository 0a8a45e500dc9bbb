package com.example.gdxmeadow;

import com.badlogic.gdx.ApplicationAdapter;
import com.badlogic.gdx.Gdx;
import com.badlogic.gdx.Input.Keys;
import com.badlogic.gdx.assets.AssetManager;
import com.badlogic.gdx.assets.loaders.FileHandleResolver;
import com.badlogic.gdx.graphics.Color;
import com.badlogic.gdx.graphics.GL20;
import com.badlogic.gdx.graphics.PerspectiveCamera;
import com.badlogic.gdx.graphics.Pixmap;
import com.badlogic.gdx.graphics.Texture;
import com.badlogic.gdx.graphics.VertexAttributes.Usage;
import com.badlogic.gdx.graphics.g2d.BitmapFont;
import com.badlogic.gdx.graphics.g2d.GlyphLayout;
import com.badlogic.gdx.graphics.g2d.SpriteBatch;
import com.badlogic.gdx.graphics.g3d.Environment;
import com.badlogic.gdx.graphics.g3d.Material;
import com.badlogic.gdx.graphics.g3d.Model;
import com.badlogic.gdx.graphics.g3d.ModelBatch;
import com.badlogic.gdx.graphics.g3d.ModelInstance;
import com.badlogic.gdx.graphics.g3d.attributes.ColorAttribute;
import com.badlogic.gdx.graphics.g3d.environment.DirectionalLight;
import com.badlogic.gdx.graphics.g3d.utils.ModelBuilder;
import com.badlogic.gdx.math.Vector3;
import com.badlogic.gdx.utils.GdxRuntimeException;
import com.badlogic.gdx.utils.ScreenUtils;
import org.jecosys.gdx.GdxScenes;
import org.jecosys.gdx.PlantLayer;
import org.jecosys.gdx.PlantLayerLoader;
import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;

/**
 * A small libGDX game around JEcoSys plants. Each frame, in {@link #render()}: the game moves its
 * player and its camera, steps the plants ({@code plants.update(Gdx.graphics.getDeltaTime(), camera)}),
 * clears, draws its ground and player with a {@code ModelBatch}, lets JEcoSys draw the plants, and
 * draws its HUD with a {@code SpriteBatch}. The scene loads through libGDX's {@code AssetManager}
 * ({@link PlantLayerLoader}: read and built on the loader thread) while a loading line shows.
 *
 * <p>The player walks a loop through the grass; a source flow attached to it ({@code attachAgent})
 * pushes the plants aside, so a trail of bent grass follows it. Arrow keys or WASD steer it instead.
 * The test mode's {@code --start-view} leaves the player out and holds the camera at the scene's start
 * camera instead.
 */
public final class GdxMeadowGame extends ApplicationAdapter {
    /** Player flow strength, m²/s: a source of this strength blows 3.2 m/s one metre away. */
    static final double PLAYER_STRENGTH = 20;
    /** Walking speed, m/s. */
    private static final float SPEED = 1.4f;
    /** HUD text colour. */
    static final Color HUD_TEXT = new Color(1f, 0.85f, 0.1f, 1f);

    private final GdxMeadowLauncher.Options options;
    private final FileHandleResolver resolver;
    private final TestCapture capture;
    private AssetManager assets;
    private PerspectiveCamera camera;
    private ModelBatch modelBatch;
    private Environment environment;
    private Model groundModel;
    private Model playerModel;
    private ModelInstance ground;
    private ModelInstance player;
    private SpriteBatch spriteBatch;
    private BitmapFont font;
    private Texture panel;
    private final GlyphLayout hudLayout = new GlyphLayout();
    private final StringBuilder hudText = new StringBuilder(128);

    private PlantLayer plants;
    private WindSource playerFlow;
    private Heightfield terrain;
    private float centreX;
    private float centreZ;
    private float loopRadius;
    private float time;
    private float playerX;
    private float playerZ;
    private float heading;
    private final Vector3 eye = new Vector3();
    private final Vector3 target = new Vector3();

    GdxMeadowGame(GdxMeadowLauncher.Options options, FileHandleResolver resolver) {
        this.options = options;
        this.resolver = resolver;
        this.capture = options.frames() > 0 ? new TestCapture(options) : null;
    }

    @Override
    public void create() {
        camera = new PerspectiveCamera(55, Gdx.graphics.getWidth(), Gdx.graphics.getHeight());
        camera.near = 0.05f;
        camera.far = 300f;
        modelBatch = new ModelBatch();
        environment = new Environment();
        environment.set(new ColorAttribute(ColorAttribute.AmbientLight, 0.45f, 0.45f, 0.5f, 1f));
        environment.add(new DirectionalLight().set(0.8f, 0.78f, 0.7f, -0.4f, -1f, 0.3f));
        playerModel = new ModelBuilder().createCapsule(0.25f, 1.7f, 12,
                new Material(ColorAttribute.createDiffuse(new Color(0.15f, 0.3f, 0.95f, 1f))),
                Usage.Position | Usage.Normal);
        player = new ModelInstance(playerModel);
        spriteBatch = new SpriteBatch();
        font = new BitmapFont();
        font.getData().setScale(1.25f);
        Pixmap px = new Pixmap(1, 1, Pixmap.Format.RGBA8888);
        px.setColor(0f, 0f, 0f, 0.55f);
        px.fill();
        panel = new Texture(px);
        px.dispose();

        assets = new AssetManager(resolver);
        assets.setLoader(PlantLayer.class, new PlantLayerLoader(resolver));
        assets.load(options.scene(), PlantLayer.class);
    }

    /** The scene is loaded: the ground from its heightfield, the player's flow, the camera's start. */
    private void start(PlantLayer layer) {
        plants = layer;
        Simulation sim = plants.simulation();
        terrain = sim.world().terrain().heightfield();
        groundModel = GroundModel.of(terrain);
        ground = new ModelInstance(groundModel);
        centreX = (float) (terrain.minX() + terrain.sizeX() / 2);
        centreZ = (float) (terrain.minZ() + terrain.sizeZ() / 2);
        loopRadius = (float) Math.min(terrain.sizeX(), terrain.sizeZ()) * 0.2f;
        if (options.startView()) {
            startView();
            return;
        }
        walk(0);
        playerFlow = sim.attachAgent(FlowDef.point("player", FlowKind.SOURCE, playerX, playerZ,
                options.playerStrength()));
    }

    /**
     * The test mode's still camera: the scene's start camera ({@code <camera>}, its height above the
     * ground under it), with its lens, as the library's viewer opens the scene.
     */
    private void startView() {
        CameraDef c;
        try {
            c = GdxScenes.read(resolver.resolve(options.scene())).def().camera();
        } catch (SceneLoadException e) {
            throw new GdxRuntimeException(e.getMessage(), e);
        }
        ViewCamera v = ViewCamera.of(c, terrain.height(c.x(), c.z()),
                Gdx.graphics.getWidth() / (double) Gdx.graphics.getHeight());
        org.joml.Vector3f ahead = v.forward(new org.joml.Vector3f());
        camera.fieldOfView = (float) Math.toDegrees(v.fovY());
        camera.near = (float) v.near();
        camera.far = (float) v.far();
        camera.position.set((float) v.x(), (float) v.y(), (float) v.z());
        camera.direction.set(ahead.x, ahead.y, ahead.z);
        camera.up.set(Vector3.Y);
        camera.viewportWidth = Gdx.graphics.getWidth();
        camera.viewportHeight = Gdx.graphics.getHeight();
        camera.update();
    }

    @Override
    public void render() {
        if (plants == null) {
            if (assets.update()) {
                start(assets.get(options.scene(), PlantLayer.class));
            } else {
                ScreenUtils.clear(0.1f, 0.12f, 0.15f, 1f, true);
                drawHud("Loading " + options.scene() + " ... " + Math.round(100 * assets.getProgress()) + "%");
                return;
            }
        }
        // a fixed frame time in the test mode, so that its pictures do not depend on the machine's speed
        float dt = capture != null ? 1 / 30f : Gdx.graphics.getDeltaTime();
        time += dt;
        if (playerFlow != null) {
            walk(dt);
            plants.simulation().moveAgent(playerFlow, playerX, playerZ);
            follow();
        }
        plants.update(dt, camera);

        ScreenUtils.clear(0.55f, 0.72f, 0.92f, 1f, true);
        modelBatch.begin(camera);
        modelBatch.render(ground, environment);
        if (playerFlow != null) {
            modelBatch.render(player, environment);
        }
        modelBatch.end();
        checkGl("ModelBatch");
        if (capture != null) {
            capture.beforePlants();
        }
        plants.render(camera, environment); // between the 3D and 2D passes, depth-tested, in the game's light
        checkGl("plants");
        if (capture != null) {
            capture.afterPlants();
        }
        hudText.setLength(0);
        hudText.append("JEcoSys in libGDX: ").append(plants.simulation().plantCount()).append(" plants, ")
                .append(Gdx.graphics.getFramesPerSecond()).append(" fps; WASD walks");
        drawHud(hudText);
        checkGl("SpriteBatch");
        if (capture != null && capture.frameDone(this)) {
            Gdx.app.exit();
        }
    }

    /** The player: the scripted loop, or the keys when one is held. */
    private void walk(float dt) {
        float turn = 0;
        float ahead = 0;
        if (Gdx.input != null && capture == null) {
            if (Gdx.input.isKeyPressed(Keys.LEFT) || Gdx.input.isKeyPressed(Keys.A)) {
                turn += 1;
            }
            if (Gdx.input.isKeyPressed(Keys.RIGHT) || Gdx.input.isKeyPressed(Keys.D)) {
                turn -= 1;
            }
            if (Gdx.input.isKeyPressed(Keys.UP) || Gdx.input.isKeyPressed(Keys.W)) {
                ahead += 1;
            }
            if (Gdx.input.isKeyPressed(Keys.DOWN) || Gdx.input.isKeyPressed(Keys.S)) {
                ahead -= 1;
            }
        }
        if (turn != 0 || ahead != 0) {
            heading += 1.8f * turn * dt;
            playerX += (float) Math.cos(heading) * SPEED * ahead * dt;
            playerZ += (float) Math.sin(heading) * SPEED * ahead * dt;
            playerX = (float) Math.max(terrain.minX() + 0.5, Math.min(terrain.maxX() - 0.5, playerX));
            playerZ = (float) Math.max(terrain.minZ() + 0.5, Math.min(terrain.maxZ() - 0.5, playerZ));
        } else {
            // the loop: a circle around the middle of the field, walked counter-clockwise seen from above
            float a = time * SPEED / loopRadius;
            playerX = centreX + loopRadius * (float) Math.cos(a);
            playerZ = centreZ - loopRadius * (float) Math.sin(a);
            heading = -a - (float) Math.PI / 2;
        }
        float y = (float) terrain.height(playerX, playerZ);
        player.transform.setToTranslation(playerX, y + 0.85f, playerZ);
    }

    /** The camera: behind the player and above it, looking a little ahead of it. */
    private void follow() {
        float fx = (float) Math.cos(heading);
        float fz = (float) Math.sin(heading);
        float ex = playerX - 3.2f * fx;
        float ez = playerZ - 3.2f * fz;
        eye.set(ex, (float) terrain.height(ex, ez) + 2.6f, ez);
        target.set(playerX + 1.5f * fx, (float) terrain.height(playerX, playerZ) + 0.2f, playerZ + 1.5f * fz);
        camera.position.set(eye);
        camera.up.set(Vector3.Y);
        camera.lookAt(target);
        camera.viewportWidth = Gdx.graphics.getWidth();
        camera.viewportHeight = Gdx.graphics.getHeight();
        camera.update();
    }

    /** The HUD: a dark panel with a line of text, top left. */
    private void drawHud(CharSequence text) {
        font.setColor(HUD_TEXT);
        hudLayout.setText(font, text);
        float x = 12;
        float top = Gdx.graphics.getHeight() - 12;
        spriteBatch.getProjectionMatrix().setToOrtho2D(0, 0, Gdx.graphics.getWidth(), Gdx.graphics.getHeight());
        spriteBatch.begin();
        spriteBatch.draw(panel, x - 6, top - hudLayout.height - 8, hudLayout.width + 12, hudLayout.height + 16);
        font.draw(spriteBatch, hudLayout, x, top);
        spriteBatch.end();
    }

    private void checkGl(String phase) {
        if (capture != null) {
            capture.checkGl(phase);
        }
    }

    @Override
    public void resize(int width, int height) {
        if (camera != null) {
            camera.viewportWidth = width;
            camera.viewportHeight = height;
        }
    }

    @Override
    public void dispose() {
        assets.dispose(); // disposes the plant layer (GL objects, simulation)
        modelBatch.dispose();
        if (groundModel != null) {
            groundModel.dispose();
        }
        playerModel.dispose();
        spriteBatch.dispose();
        font.dispose();
        panel.dispose();
    }

    // what the test mode reads
    PerspectiveCamera camera() {
        return camera;
    }

    PlantLayer plants() {
        return plants;
    }

    float playerX() {
        return playerX;
    }

    float playerZ() {
        return playerZ;
    }

    GlyphLayout hudLayout() {
        return hudLayout;
    }
}
