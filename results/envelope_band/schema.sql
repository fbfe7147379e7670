-- Campaign envelope_band as SQLite tables: in this folder, `sqlite3 envelope_band.sqlite < schema.sql` (sqlite3 3.32 or
-- later) makes tables trials (trials.csv) and summary (summary.csv), their columns typed, an empty
-- field NULL, and provenance, provenance_inputs and provenance_overrides (summary.json's).
BEGIN;
DROP TABLE IF EXISTS trials;
CREATE TABLE trials (
  "foot" TEXT NOT NULL,
  "terrain" TEXT NOT NULL,
  "robot" TEXT NOT NULL,
  "springs.scale" REAL,
  "robot.com_height_m" REAL,
  "band_end" TEXT NOT NULL,
  "seed" INTEGER NOT NULL,
  "x_m" REAL,
  "y_m" REAL,
  "yaw_deg" REAL,
  "pitch_deg" REAL,
  "roll_deg" REAL,
  "outcome" TEXT NOT NULL,
  "rule" TEXT NOT NULL,
  "end_time_s" REAL,
  "touchdown_s" REAL,
  "peak_tilt_deg" REAL,
  "final_tilt_deg" REAL,
  "peak_force_N" REAL,
  "impact_impulse_Ns" REAL,
  "settle_time_s" REAL,
  "mean_contacts" REAL,
  "final_contacts" REAL,
  "ankle_drop_m" REAL,
  "slip_m" REAL,
  "steps" INTEGER,
  "rest_ankle_drop_m" REAL,
  "soil_sinkage_m" REAL,
  "print_depth_m" REAL,
  "print_area_m2" REAL,
  "print_volume_m3" REAL,
  "print_slip_m" REAL,
  "failure" TEXT
);
.import --csv --skip 1 trials.csv trials
UPDATE trials SET "foot" = NULLIF("foot", ''), "terrain" = NULLIF("terrain", ''), "robot" = NULLIF("robot", ''), "springs.scale" = NULLIF("springs.scale", ''), "robot.com_height_m" = NULLIF("robot.com_height_m", ''), "band_end" = NULLIF("band_end", ''), "seed" = NULLIF("seed", ''), "x_m" = NULLIF("x_m", ''), "y_m" = NULLIF("y_m", ''), "yaw_deg" = NULLIF("yaw_deg", ''), "pitch_deg" = NULLIF("pitch_deg", ''), "roll_deg" = NULLIF("roll_deg", ''), "outcome" = NULLIF("outcome", ''), "rule" = NULLIF("rule", ''), "end_time_s" = NULLIF("end_time_s", ''), "touchdown_s" = NULLIF("touchdown_s", ''), "peak_tilt_deg" = NULLIF("peak_tilt_deg", ''), "final_tilt_deg" = NULLIF("final_tilt_deg", ''), "peak_force_N" = NULLIF("peak_force_N", ''), "impact_impulse_Ns" = NULLIF("impact_impulse_Ns", ''), "settle_time_s" = NULLIF("settle_time_s", ''), "mean_contacts" = NULLIF("mean_contacts", ''), "final_contacts" = NULLIF("final_contacts", ''), "ankle_drop_m" = NULLIF("ankle_drop_m", ''), "slip_m" = NULLIF("slip_m", ''), "steps" = NULLIF("steps", ''), "rest_ankle_drop_m" = NULLIF("rest_ankle_drop_m", ''), "soil_sinkage_m" = NULLIF("soil_sinkage_m", ''), "print_depth_m" = NULLIF("print_depth_m", ''), "print_area_m2" = NULLIF("print_area_m2", ''), "print_volume_m3" = NULLIF("print_volume_m3", ''), "print_slip_m" = NULLIF("print_slip_m", ''), "failure" = NULLIF("failure", '');
DROP TABLE IF EXISTS summary;
CREATE TABLE summary (
  "foot" TEXT NOT NULL,
  "terrain" TEXT NOT NULL,
  "robot" TEXT NOT NULL,
  "springs.scale" REAL,
  "robot.com_height_m" REAL,
  "trials" INTEGER NOT NULL,
  "landed" INTEGER NOT NULL,
  "fell" INTEGER NOT NULL,
  "undecided" INTEGER NOT NULL,
  "failed_numerics" INTEGER NOT NULL,
  "hung" INTEGER NOT NULL,
  "success_rate" REAL,
  "ci_low" REAL,
  "ci_high" REAL,
  "median_end_time_s" REAL,
  "median_touchdown_s" REAL,
  "median_peak_tilt_deg" REAL,
  "median_final_tilt_deg" REAL,
  "median_peak_force_N" REAL,
  "median_impact_impulse_Ns" REAL,
  "median_settle_time_s" REAL,
  "median_mean_contacts" REAL,
  "median_final_contacts" REAL,
  "median_ankle_drop_m" REAL,
  "median_slip_m" REAL,
  "median_steps" REAL,
  "median_rest_ankle_drop_m" REAL,
  "median_soil_sinkage_m" REAL,
  "median_print_depth_m" REAL,
  "median_print_area_m2" REAL,
  "median_print_volume_m3" REAL,
  "median_print_slip_m" REAL,
  "law_prediction" TEXT,
  "law_K_N_m_per_rad" REAL,
  "law_critical_com_height_m" REAL,
  "drop_law_prediction" TEXT,
  "drop_law_seeds" INTEGER,
  "drop_law_stands" INTEGER,
  "drop_law_energy_J" REAL,
  "drop_law_barrier_J" REAL,
  "drop_law_saturation_N_m" REAL,
  "drop_law_critical_com_height_m" REAL,
  "band_end" TEXT NOT NULL,
  "landed_low" INTEGER NOT NULL,
  "success_rate_low" REAL,
  "landed_high" INTEGER NOT NULL,
  "success_rate_high" REAL,
  "law_end" TEXT,
  "law_prediction_low" TEXT,
  "drop_law_prediction_low" TEXT,
  "drop_law_stands_low" INTEGER,
  "law_prediction_high" TEXT,
  "drop_law_prediction_high" TEXT,
  "drop_law_stands_high" INTEGER
);
.import --csv --skip 1 summary.csv summary
UPDATE summary SET "foot" = NULLIF("foot", ''), "terrain" = NULLIF("terrain", ''), "robot" = NULLIF("robot", ''), "springs.scale" = NULLIF("springs.scale", ''), "robot.com_height_m" = NULLIF("robot.com_height_m", ''), "trials" = NULLIF("trials", ''), "landed" = NULLIF("landed", ''), "fell" = NULLIF("fell", ''), "undecided" = NULLIF("undecided", ''), "failed_numerics" = NULLIF("failed_numerics", ''), "hung" = NULLIF("hung", ''), "success_rate" = NULLIF("success_rate", ''), "ci_low" = NULLIF("ci_low", ''), "ci_high" = NULLIF("ci_high", ''), "median_end_time_s" = NULLIF("median_end_time_s", ''), "median_touchdown_s" = NULLIF("median_touchdown_s", ''), "median_peak_tilt_deg" = NULLIF("median_peak_tilt_deg", ''), "median_final_tilt_deg" = NULLIF("median_final_tilt_deg", ''), "median_peak_force_N" = NULLIF("median_peak_force_N", ''), "median_impact_impulse_Ns" = NULLIF("median_impact_impulse_Ns", ''), "median_settle_time_s" = NULLIF("median_settle_time_s", ''), "median_mean_contacts" = NULLIF("median_mean_contacts", ''), "median_final_contacts" = NULLIF("median_final_contacts", ''), "median_ankle_drop_m" = NULLIF("median_ankle_drop_m", ''), "median_slip_m" = NULLIF("median_slip_m", ''), "median_steps" = NULLIF("median_steps", ''), "median_rest_ankle_drop_m" = NULLIF("median_rest_ankle_drop_m", ''), "median_soil_sinkage_m" = NULLIF("median_soil_sinkage_m", ''), "median_print_depth_m" = NULLIF("median_print_depth_m", ''), "median_print_area_m2" = NULLIF("median_print_area_m2", ''), "median_print_volume_m3" = NULLIF("median_print_volume_m3", ''), "median_print_slip_m" = NULLIF("median_print_slip_m", ''), "law_prediction" = NULLIF("law_prediction", ''), "law_K_N_m_per_rad" = NULLIF("law_K_N_m_per_rad", ''), "law_critical_com_height_m" = NULLIF("law_critical_com_height_m", ''), "drop_law_prediction" = NULLIF("drop_law_prediction", ''), "drop_law_seeds" = NULLIF("drop_law_seeds", ''), "drop_law_stands" = NULLIF("drop_law_stands", ''), "drop_law_energy_J" = NULLIF("drop_law_energy_J", ''), "drop_law_barrier_J" = NULLIF("drop_law_barrier_J", ''), "drop_law_saturation_N_m" = NULLIF("drop_law_saturation_N_m", ''), "drop_law_critical_com_height_m" = NULLIF("drop_law_critical_com_height_m", ''), "band_end" = NULLIF("band_end", ''), "landed_low" = NULLIF("landed_low", ''), "success_rate_low" = NULLIF("success_rate_low", ''), "landed_high" = NULLIF("landed_high", ''), "success_rate_high" = NULLIF("success_rate_high", ''), "law_end" = NULLIF("law_end", ''), "law_prediction_low" = NULLIF("law_prediction_low", ''), "drop_law_prediction_low" = NULLIF("drop_law_prediction_low", ''), "drop_law_stands_low" = NULLIF("drop_law_stands_low", ''), "law_prediction_high" = NULLIF("law_prediction_high", ''), "drop_law_prediction_high" = NULLIF("drop_law_prediction_high", ''), "drop_law_stands_high" = NULLIF("drop_law_stands_high", '');
DROP TABLE IF EXISTS provenance;
CREATE TABLE provenance (footsim TEXT NOT NULL, seeds INTEGER NOT NULL, first_seed INTEGER NOT NULL, settings TEXT NOT NULL);
INSERT INTO provenance VALUES ('1.0.0 (git 47f4943)', 5, 1, 'step_s 0.0001, stepper step, iterations 50, springs implicit, contact_layer_m 0.0005, window 3 s; band contact');
DROP TABLE IF EXISTS provenance_inputs;
CREATE TABLE provenance_inputs (path TEXT NOT NULL, hash TEXT NOT NULL);
INSERT INTO provenance_inputs VALUES ('envelope_band.ini', '8292f9075398ed3e');
INSERT INTO provenance_inputs VALUES ('landing_trial.ini', 'afead5744fbe9935');
INSERT INTO provenance_inputs VALUES ('feet/biomimetic.ini', '1d4a9d5346c02982');
INSERT INTO provenance_inputs VALUES ('../terrains/flat.ini', '208b9628872b96ad');
INSERT INTO provenance_inputs VALUES ('robots/single_tall.ini', '78b98fbe0bb17d36');
DROP TABLE IF EXISTS provenance_overrides;
CREATE TABLE provenance_overrides (position INTEGER NOT NULL, override TEXT NOT NULL);
COMMIT;
