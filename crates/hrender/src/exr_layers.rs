//! An OpenEXR picture with pixel layers beside its colour: the `R`, `G`,
//! `B` channels of the image and the named channels of its
//! [`AovLayers`](crate::AovLayers), all 32-bit float, ZIP-compressed, one
//! part (channels sorted by name, as OpenEXR wants them).

use std::path::Path;

use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image as ExrImage, Layer, LayerAttributes,
    WritableImage,
};

use crate::aov::AovLayers;
use crate::error::RenderError;
use crate::image::Image;
use crate::output::write_atomically;

/// Writes `image` and `layers` (of the same size) to the `.exr` file
/// `path`, atomically.
pub fn write_exr_with_layers(
    image: &Image,
    layers: &AovLayers,
    path: &Path,
) -> Result<(), RenderError> {
    if (layers.width, layers.height) != (image.width(), image.height()) {
        return Err(RenderError::InvalidOption(format!(
            "pixel layers of {}x{} for a picture of {}x{}",
            layers.width,
            layers.height,
            image.width(),
            image.height()
        )));
    }
    let colour = |c: usize| image.pixels().iter().map(|p| p[c]).collect::<Vec<f32>>();
    let mut channels = vec![
        AnyChannel::new("R", FlatSamples::F32(colour(0))),
        AnyChannel::new("G", FlatSamples::F32(colour(1))),
        AnyChannel::new("B", FlatSamples::F32(colour(2))),
    ];
    for (name, samples) in &layers.channels {
        channels.push(AnyChannel::new(*name, FlatSamples::F32(samples.clone())));
    }
    let size = (image.width() as usize, image.height() as usize);
    let layer = Layer::new(
        size,
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(channels.into()),
    );
    write_atomically(path, |out| {
        ExrImage::from_layer(layer)
            .write()
            .to_buffered(out)
            .map_err(|e| RenderError::Encode {
                path: path.to_path_buf(),
                message: e.to_string(),
            })
    })
}
