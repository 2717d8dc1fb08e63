classdef Model
  % MODEL  A compensation model: features, scalers, regressor, novelty guard and provenance.
  %
  %   m = fogdrift.Model.load('model.json')            % or fogdrift.train's first output
  %   p = m.predict(recording)                         % struct (or table) of columns, or a CSV
  %   gyro_compensated = recording.gyro_dph - p.drift_dph;
  %   m.save('copy.json')                              % the same bytes
  %   m.exportC('model.h', 'stream_rate_hz', 1)        % C99 for the firmware
  %
  %   The model is held as its file's text and checked again (checksum too) at every call.
  %
  %   See also fogdrift.train, fogdrift.evaluate.

  properties (SetAccess = private)
    text = ''  % the model file's text
  end

  methods
    function obj = Model(text)
      % MODEL  A model from a model file's text (fogdrift.Model.load reads a file).
      if nargin > 0
        obj.text = text;
        fogdrift.Model.call('model_info', text);  % checked now, not at first use
      end
    end

    function s = info(obj)
      % INFO  method, target, feature_names, hyperparameters, fitness, training_rows, causal.
      s = fogdrift.Model.call('model_info', obj.text);
    end

    function p = predict(obj, recording, varargin)
      % PREDICT  Drift at every sample: drift_dph (what to subtract), model_drift_dph, novelty,
      % guard_weight, each a column. 'guarded', false leaves the novelty guard out. A model of
      % another target names the drift in its unit (drift_g, drift_ppm).
      if exist('istable') && istable(recording) %#ok<EXIST>
        recording = table2struct(recording, 'ToScalar', true);
      end
      p = fogdrift.Model.call('model_predict', obj.text, recording, varargin{:});
    end

    function save(obj, path)
      % SAVE  Writes the model file atomically.
      fogdrift.Model.call('model_save', obj.text, path);
    end

    function exportC(obj, path, varargin)
      % EXPORTC  The model as a C99 header, as `fogdrift export-c`: 'prefix' (default
      % fogdrift_model), 'stream_rate_hz' (0: no streaming part), 'precision' ('double' or
      % 'float'), 'force_float', and the streaming fault policy's options (fogdrift.options('stream')).
      fogdrift.Model.call('model_export_c', obj.text, path, varargin{:});
    end

    function disp(obj)
      s = obj.info();
      fprintf('  fogdrift.Model: %s for %s, %d features, %d training rows\n', s.method, ...
              s.target, numel(s.feature_names), s.training_rows);
    end
  end

  methods (Static)
    function obj = load(path, varargin)
      % LOAD  Reads and checks a model file: 'target' picks one axis of a model of several,
      % 'allow_edited' loads a file whose checksum no longer matches, 'allow_old_format' a
      % file of format 1 or 2.
      obj = fogdrift.Model(fogdrift.Model.call('model_load', path, varargin{:}));
    end
  end

  methods (Static, Access = private)
    function out = call(command, varargin)
      [err, warns, out] = fogdrift_mex(command, varargin{:});
      if ~isempty(err), error(err); end
      for k = 1:numel(warns), warning('fogdrift:model', '%s', warns{k}); end
    end
  end
end
